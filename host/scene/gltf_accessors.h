// Bounds-checked reading of glTF accessors: every offset, stride and count is checked against the
// buffer view and the buffer before a byte is read, so a hostile file cannot read out of bounds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkp {

// Errors name the element: "accessors[5]: ...". The caller adds the file name.
std::vector<glm::vec3> readVec3Accessor(const tinygltf::Model& model, int accessor);
std::vector<glm::vec2> readVec2Accessor(const tinygltf::Model& model, int accessor);  // float or normalized
std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessor);

}  // namespace vkp
