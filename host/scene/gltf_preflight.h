// Checks a glTF file before tinygltf sees it. tinygltf trusts parts of its input (an image's
// bufferView range, the GLB BIN chunk length, deep JSON nesting) and words its errors without
// naming the element; the preflight refuses all of that first, naming the element.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "scene/gltf_files.h"
#include "scene/gltf_loader.h"

namespace vkp {

struct GltfDocument {
    std::vector<unsigned char> bytes;  // the whole .gltf or .glb
    bool binary = false;               // .glb container (detected by its magic, not the extension)
};

// Reads `path` and checks: size limits; the GLB container; JSON syntax and nesting depth;
// asset.version 2.x; extensionsRequired; that every index reference (scene, nodes, meshes,
// accessors, bufferViews, buffers, images, textures, materials, cameras, lights) exists; every
// bufferView lies inside its buffer; every buffer and image URI passes uriRefusalReason() and
// names an existing file of acceptable size inside the scene's folder (registering buffer
// lengths with `files`); data: URIs decode to the declared length. Throws InputError with
// "ELEMENT: problem" (the caller prefixes the file name).
GltfDocument preflightGltf(const std::filesystem::path& path, const GltfLimits& limits, GltfFileAccess& files);

}  // namespace vkp
