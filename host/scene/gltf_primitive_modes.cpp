#include "scene/gltf_primitive_modes.h"

#include <cstddef>

namespace vkp {
namespace {

constexpr int kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;

}  // namespace

bool isTriangleMode(int mode) {
    return mode == -1 || mode == kTriangles || mode == kTriangleStrip || mode == kTriangleFan;
}

uint64_t triangleCountOfMode(int mode, uint64_t vertices) {
    if (mode == kTriangleStrip || mode == kTriangleFan) return vertices >= 3 ? vertices - 2 : 0;
    return isTriangleMode(mode) ? vertices / 3 : 0;
}

std::vector<uint32_t> triangleListIndices(int mode, const std::vector<uint32_t>& indices) {
    if (mode != kTriangleStrip && mode != kTriangleFan) return indices;
    const size_t triangles = triangleCountOfMode(mode, indices.size());
    std::vector<uint32_t> list;
    list.reserve(3 * triangles);
    for (size_t i = 0; i < triangles; ++i) {
        if (mode == kTriangleStrip) {
            list.push_back(indices[i]);
            list.push_back(indices[i + 1 + i % 2]);
            list.push_back(indices[i + 2 - i % 2]);
        } else {
            list.push_back(indices[i + 1]);
            list.push_back(indices[i + 2]);
            list.push_back(indices[0]);
        }
    }
    return list;
}

}  // namespace vkp
