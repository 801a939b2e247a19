// KHR_draco_mesh_compression: each compressed primitive's Draco stream is decoded (Debian's
// libdraco) into a new buffer, and the primitive's accessors (which carry count, type and
// min/max but no bufferView) are pointed at it: FLOAT attributes, UNSIGNED_INT indices. The rest
// of the loader then reads them like any other accessor, bounds checks included.
#pragma once

#include <tiny_gltf.h>

namespace vkp {

// Throws InputError naming the element ("meshes[0].primitives[1].extensions.KHR_draco_mesh_compression: ...")
// for a bad reference, a corrupt stream, or counts that disagree with the accessors.
void decodeDracoPrimitives(tinygltf::Model& model);

}  // namespace vkp
