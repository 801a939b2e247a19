// Bounds-checked reading of glTF accessors: every offset, stride and count is checked against the
// buffer view and the buffer before a byte is read, so a hostile file cannot read out of bounds.
// Supports every component type (normalized or not, as KHR_mesh_quantization allows), interleaved
// views, accessors without a bufferView (zeros) and sparse accessors.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkp {

// Errors are InputErrors naming the element: "accessors[5]: ...". The caller adds the file name.
std::vector<glm::vec3> readVec3Accessor(const tinygltf::Model& model, int accessor);
std::vector<glm::vec2> readVec2Accessor(const tinygltf::Model& model, int accessor);
std::vector<glm::vec4> readVec4Accessor(const tinygltf::Model& model, int accessor);
// MAT4 float, column-major (skins' inverseBindMatrices).
std::vector<glm::dmat4> readMat4Accessor(const tinygltf::Model& model, int accessor);
std::vector<float> readScalarAccessor(const tinygltf::Model& model, int accessor);  // SCALAR (animation times)
// COLOR_0: VEC3 (alpha 1) or VEC4, float or normalized unsigned byte/short.
std::vector<glm::vec4> readColorAccessor(const tinygltf::Model& model, int accessor);
std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessor);  // unsigned types only

}  // namespace vkp
