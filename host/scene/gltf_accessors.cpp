#include "scene/gltf_accessors.h"

#include <cstring>

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {
namespace {

size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

int componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
    }
}

struct View {
    const unsigned char* data = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int componentType = 0;
    int components = 0;
};

// Validates accessor -> bufferView -> buffer and returns where element i starts (data + i*stride).
View checkedView(const tinygltf::Model& model, int index, int wantComponents) {
    const std::string name = fmt::format("accessors[{}]", index);
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
        throw InputError(fmt::format("{}: no such accessor ({} exist)", name, model.accessors.size()));
    const tinygltf::Accessor& a = model.accessors[index];
    if (a.sparse.isSparse) throw InputError(fmt::format("{}: sparse accessors are not supported", name));
    View v;
    v.componentType = a.componentType;
    v.components = componentCount(a.type);
    v.count = a.count;
    const size_t compSize = componentSize(a.componentType);
    if (compSize == 0 || v.components != wantComponents)
        throw InputError(fmt::format("{}: expected {} components of a valid component type", name, wantComponents));
    const size_t elementSize = compSize * v.components;
    if (a.count == 0) return v;
    if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model.bufferViews.size())
        throw InputError(fmt::format("{}: bufferView {} does not exist", name, a.bufferView));
    const tinygltf::BufferView& bv = model.bufferViews[a.bufferView];
    const std::string viewName = fmt::format("bufferViews[{}]", a.bufferView);
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model.buffers.size())
        throw InputError(fmt::format("{}: buffer {} does not exist", viewName, bv.buffer));
    const tinygltf::Buffer& buffer = model.buffers[bv.buffer];
    if (bv.byteOffset > buffer.data.size() || bv.byteLength > buffer.data.size() - bv.byteOffset)
        throw InputError(fmt::format("{}: bytes [{}, {}) exceed buffers[{}] ({} bytes)", viewName, bv.byteOffset,
                                     bv.byteOffset + bv.byteLength, bv.buffer, buffer.data.size()));
    v.stride = bv.byteStride ? bv.byteStride : elementSize;
    if (v.stride < elementSize) throw InputError(fmt::format("{}: byteStride {} is smaller than an element", viewName, v.stride));
    const size_t last = a.byteOffset + v.stride * (a.count - 1) + elementSize;
    if (a.byteOffset > bv.byteLength || last > bv.byteLength || (a.count - 1) > (SIZE_MAX / v.stride))
        throw InputError(fmt::format("{}: {} elements at offset {} need {} bytes but {} has {}", name, a.count,
                                     a.byteOffset, last, viewName, bv.byteLength));
    v.data = buffer.data.data() + bv.byteOffset + a.byteOffset;
    return v;
}

float readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t s; std::memcpy(&s, p, 2); return normalized ? s / 65535.0f : s; }
    case TINYGLTF_COMPONENT_TYPE_BYTE: { int8_t b; std::memcpy(&b, p, 1); return normalized ? std::max(b / 127.0f, -1.0f) : b; }
    case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t s; std::memcpy(&s, p, 2); return normalized ? std::max(s / 32767.0f, -1.0f) : s; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t u; std::memcpy(&u, p, 4); return static_cast<float>(u); }
    default: return 0.0f;
    }
}

template <int N>
std::vector<glm::vec<N, float>> readFloats(const tinygltf::Model& model, int index) {
    const View v = checkedView(model, index, N);
    const bool normalized = model.accessors[index].normalized;
    const size_t compSize = componentSize(v.componentType);
    std::vector<glm::vec<N, float>> out(v.count);
    for (size_t i = 0; i < v.count; ++i)
        for (int c = 0; c < N; ++c) out[i][c] = readComponent(v.data + i * v.stride + c * compSize, v.componentType, normalized);
    return out;
}

}  // namespace

std::vector<glm::vec3> readVec3Accessor(const tinygltf::Model& model, int accessor) {
    return readFloats<3>(model, accessor);
}

std::vector<glm::vec2> readVec2Accessor(const tinygltf::Model& model, int accessor) {
    return readFloats<2>(model, accessor);
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessor) {
    const View v = checkedView(model, accessor, 1);
    if (v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw InputError(fmt::format("accessors[{}]: indices must be unsigned byte, short or int", accessor));
    std::vector<uint32_t> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
        const unsigned char* p = v.data + i * v.stride;
        if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) out[i] = p[0];
        else if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) { uint16_t s; std::memcpy(&s, p, 2); out[i] = s; }
        else std::memcpy(&out[i], p, 4);
    }
    return out;
}

}  // namespace vkp
