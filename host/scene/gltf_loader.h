// glTF 2.0 (.gltf / .glb) loading through tinygltf into a flattened vkp::Scene.
#pragma once

#include <cstdint>
#include <filesystem>

#include "scene/scene.h"

namespace vkp {

// Limits that keep a hostile file from exhausting memory.
struct GltfLimits {
    uint64_t maxFileBytes = 2ull << 30;       // the .gltf/.glb itself and each external buffer
    uint32_t maxImageDimension = 16384;       // width and height of any texture
    uint64_t maxImagePixels = 64ull << 20;    // width * height of any texture
    uint64_t maxTotalImagePixels = 256ull << 20;  // all images of the file together (1 GiB as RGBA8)
    uint64_t maxTriangles = 1ull << 26;
};

// Loads the default scene (or scene 0) of a glTF file. Throws vkp::InputError with a message of
// the form "FILE: ELEMENT: what is wrong" (e.g. "box.gltf: meshes[2].primitives[0]: ...") for
// any bad input; never crashes on malformed files. Buffer and image URIs that are absolute, leave
// the file's folder (".."), or contain shell expansion characters are refused.
Scene loadGltf(const std::filesystem::path& path, const GltfLimits& limits = {});

}  // namespace vkp
