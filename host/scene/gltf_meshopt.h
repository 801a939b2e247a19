// EXT_meshopt_compression (and KHR_meshopt_compression, same layout, as far as Debian's
// meshoptimizer 0.18 decodes it): bufferViews whose bytes are stored compressed in another
// buffer. Each is decoded (meshopt_decodeVertexBuffer / IndexBuffer / IndexSequence, then the
// OCTAHEDRAL / QUATERNION / EXPONENTIAL filter) into the bufferView's own place, so accessors
// read it as usual. A fallback buffer may have no uri: tinygltf cannot load such a buffer, so
// the document's JSON is rewritten before parsing to give it a one-byte placeholder, and the
// buffer is sized (zeros) before decoding.
#pragma once

#include <cstdint>
#include <map>

#include <tiny_gltf.h>

#include "scene/gltf_preflight.h"

namespace vkp {

// Buffer index -> its real byteLength, for each uri-less fallback buffer the JSON was changed for.
using MeshoptFallbacks = std::map<int, uint64_t>;

// Changes `document` (its JSON, repacking a .glb) only when it names a meshopt extension or
// KHR_draco_mesh_compression (whose index accessors, having no bufferView, tinygltf refuses:
// they get the Draco view as a placeholder, replaced when the stream is decoded).
MeshoptFallbacks prepareMeshoptFallbacks(GltfDocument& document);

// Throws InputError naming the bufferView for a bad reference or a corrupt stream.
void decodeMeshoptViews(tinygltf::Model& model, const MeshoptFallbacks& fallbacks);

}  // namespace vkp
