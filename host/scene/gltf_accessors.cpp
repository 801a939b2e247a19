#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {
namespace {

// An accessor without a bufferView is all zeros (plus sparse substitutions); nothing in the file
// bounds its count, so this does.
constexpr size_t kMaxElementsWithoutData = size_t(1) << 24;

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

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


bool isUnsignedInteger(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Elements laid out in a buffer: element i starts at data + i * stride.
struct Span {
    const unsigned char* data = nullptr;
    size_t stride = 0;
};

// Validates that `count` elements of `elementSize` bytes, `stride` apart (0: the view's
// byteStride, or tightly packed), starting `byteOffset` into bufferViews[viewIndex], lie inside
// the view and the view inside its buffer's actual data.
Span checkedSpan(const tinygltf::Model& model, int viewIndex, uint64_t byteOffset, size_t stride, size_t count,
                 size_t elementSize, const std::string& element) {
    if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size())
        fail(element, fmt::format("bufferViews[{}] does not exist", viewIndex));
    const tinygltf::BufferView& view = model.bufferViews[viewIndex];
    const std::string viewName = fmt::format("bufferViews[{}]", viewIndex);
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        fail(viewName, fmt::format("buffers[{}] does not exist", view.buffer));
    const size_t bufferSize = model.buffers[view.buffer].data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset)
        fail(viewName, fmt::format("bytes [{}, {}) exceed buffers[{}] ({} bytes)", view.byteOffset,
                                   view.byteOffset + view.byteLength, view.buffer, bufferSize));
    Span span;
    span.stride = stride ? stride : view.byteStride ? view.byteStride : elementSize;
    if (span.stride < elementSize)
        fail(viewName, fmt::format("byteStride {} is smaller than an element ({} bytes)", span.stride, elementSize));
    // count elements need (count - 1) * stride + elementSize bytes after byteOffset; written so
    // that nothing overflows.
    const size_t available = byteOffset <= view.byteLength ? view.byteLength - byteOffset : 0;
    const bool fits = count == 0 || (available >= elementSize && (count - 1) <= (available - elementSize) / span.stride);
    if (byteOffset > view.byteLength || !fits)
        fail(element, fmt::format("{} elements of {} bytes, {} apart, from byte {} do not fit in {} ({} bytes)", count,
                                  elementSize, span.stride, byteOffset, viewName, view.byteLength));
    span.data = model.buffers[view.buffer].data.data() + view.byteOffset + byteOffset;
    return span;
}

double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t s; std::memcpy(&s, p, 2); return normalized ? s / 65535.0 : s; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t u; std::memcpy(&u, p, 4); return u; }
    // Signed normalized: the glTF rule max(c / (2^(n-1) - 1), -1).
    case TINYGLTF_COMPONENT_TYPE_BYTE: { int8_t b; std::memcpy(&b, p, 1); return normalized ? std::max(b / 127.0, -1.0) : b; }
    case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t s; std::memcpy(&s, p, 2); return normalized ? std::max(s / 32767.0, -1.0) : s; }
    default: return 0.0;
    }
}

// Validates accessors[index] (which must have `components` components) and everything it reads,
// then calls resize(count) and store(element, component, value) for every component: the dense
// data (or zeros without a bufferView), then the sparse substitutions.
template <typename Resize, typename Store>
void decode(const tinygltf::Model& model, int index, int components, Resize&& resize, Store&& store) {
    const std::string name = fmt::format("accessors[{}]", index);
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
        fail(name, fmt::format("does not exist (the file has {})", model.accessors.size()));
    const tinygltf::Accessor& a = model.accessors[index];
    const size_t compSize = componentSize(a.componentType);
    if (compSize == 0) fail(name, fmt::format("invalid componentType {}", a.componentType));
    static constexpr const char* kTypeNames[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    if (tinygltf::GetNumComponentsInType(a.type) != components)
        fail(name, fmt::format("the type must be {}", components == 16 ? "MAT4" : kTypeNames[components]));
    const size_t elementSize = compSize * components;
    Span dense;
    if (a.bufferView >= 0) dense = checkedSpan(model, a.bufferView, a.byteOffset, 0, a.count, elementSize, name);
    else if (a.count > kMaxElementsWithoutData)
        fail(name, fmt::format("{} elements without a bufferView exceed the limit of {}", a.count, kMaxElementsWithoutData));

    const auto& sparse = a.sparse;
    const std::string sparseName = name + ".sparse";
    const size_t sparseCount = a.sparse.isSparse ? static_cast<size_t>(std::max(sparse.count, 0)) : 0;
    const size_t indexSize = componentSize(sparse.indices.componentType);
    Span indices, values;
    if (a.sparse.isSparse) {
        if (sparse.count < 0 || sparseCount > a.count)
            fail(sparseName, fmt::format("count {} is not in [0, {}]", sparse.count, a.count));
        if (!isUnsignedInteger(sparse.indices.componentType) || sparse.indices.byteOffset < 0 ||
            sparse.values.byteOffset < 0)
            fail(sparseName, "indices need an unsigned componentType and offsets must be non-negative");
        indices = checkedSpan(model, sparse.indices.bufferView, sparse.indices.byteOffset, indexSize, sparseCount,
                              indexSize, sparseName + ".indices");
        values = checkedSpan(model, sparse.values.bufferView, sparse.values.byteOffset, elementSize, sparseCount,
                             elementSize, sparseName + ".values");
    }

    resize(a.count);
    const auto storeElement = [&](size_t i, const unsigned char* p) {
        for (int c = 0; c < components; ++c) store(i, c, readComponent(p + c * compSize, a.componentType, a.normalized));
    };
    for (size_t i = 0; i < a.count; ++i) {
        if (dense.data) storeElement(i, dense.data + i * dense.stride);
        else for (int c = 0; c < components; ++c) store(i, c, 0.0);
    }
    for (size_t s = 0; s < sparseCount; ++s) {
        const double target = readComponent(indices.data + s * indexSize, sparse.indices.componentType, false);
        if (target >= static_cast<double>(a.count))
            fail(sparseName, fmt::format("index {} is out of range (count {})", target, a.count));
        storeElement(static_cast<size_t>(target), values.data + s * elementSize);
    }
}

template <int N>
std::vector<glm::vec<N, float>> readFloats(const tinygltf::Model& model, int index) {
    std::vector<glm::vec<N, float>> out;
    decode(model, index, N, [&](size_t count) { out.resize(count); },
           [&](size_t i, int c, double v) { out[i][c] = static_cast<float>(v); });
    return out;
}

}  // namespace

std::vector<glm::vec3> readVec3Accessor(const tinygltf::Model& model, int accessor) { return readFloats<3>(model, accessor); }

std::vector<glm::vec2> readVec2Accessor(const tinygltf::Model& model, int accessor) { return readFloats<2>(model, accessor); }

std::vector<glm::vec4> readVec4Accessor(const tinygltf::Model& model, int accessor) { return readFloats<4>(model, accessor); }

std::vector<float> readScalarAccessor(const tinygltf::Model& model, int accessor) {
    std::vector<float> out;
    decode(model, accessor, 1, [&](size_t count) { out.resize(count); },
           [&](size_t i, int, double v) { out[i] = static_cast<float>(v); });
    return out;
}

std::vector<glm::dmat4> readMat4Accessor(const tinygltf::Model& model, int accessor) {
    if (accessor >= 0 && static_cast<size_t>(accessor) < model.accessors.size() &&
        model.accessors[accessor].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        fail(fmt::format("accessors[{}]", accessor), "matrices must be float");
    std::vector<glm::dmat4> out;
    // Column-major, as glm stores it: component c is column c / 4, row c % 4.
    decode(model, accessor, 16, [&](size_t count) { out.resize(count); },
           [&](size_t i, int c, double v) { out[i][c / 4][c % 4] = v; });
    return out;
}

std::vector<glm::vec4> readColorAccessor(const tinygltf::Model& model, int accessor) {
    const std::string name = fmt::format("accessors[{}]", accessor);
    if (accessor < 0 || static_cast<size_t>(accessor) >= model.accessors.size())
        fail(name, fmt::format("does not exist (the file has {})", model.accessors.size()));
    const tinygltf::Accessor& a = model.accessors[accessor];
    const bool normalizedUnsigned = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                     a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedUnsigned)
        fail(name, "COLOR_0 must be float or normalized unsigned byte or short");
    if (a.type == TINYGLTF_TYPE_VEC4) return readFloats<4>(model, accessor);
    if (a.type != TINYGLTF_TYPE_VEC3) fail(name, "COLOR_0 must be VEC3 or VEC4");
    std::vector<glm::vec4> out;
    for (const glm::vec3& c : readFloats<3>(model, accessor)) out.emplace_back(c, 1.0f);
    return out;
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessor) {
    if (accessor >= 0 && static_cast<size_t>(accessor) < model.accessors.size() &&
        (!isUnsignedInteger(model.accessors[accessor].componentType) || model.accessors[accessor].normalized))
        fail(fmt::format("accessors[{}]", accessor), "indices must be unsigned byte, short or int, not normalized");
    std::vector<uint32_t> out;
    decode(model, accessor, 1, [&](size_t count) { out.resize(count); },
           [&](size_t i, int, double v) { out[i] = static_cast<uint32_t>(v); });
    return out;
}

}  // namespace vkp
