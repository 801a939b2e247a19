#include "scene/gltf_draco.h"

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <draco/compression/decode.h>
#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {
namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";
// Decoded points or indices per primitive: compressed data can legitimately expand a lot, but
// not without bound.
constexpr size_t kMaxDecodedElements = size_t(1) << 26;

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}


// Appends `bytes` as a new buffer with one bufferView over it, and points the accessor at it.
void attach(tinygltf::Model& model, int accessorIndex, std::vector<unsigned char> bytes, int componentType) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteOffset = 0;
    view.byteLength = buffer.data.size();
    model.buffers.push_back(std::move(buffer));
    tinygltf::Accessor& accessor = model.accessors[accessorIndex];
    accessor.bufferView = static_cast<int>(model.bufferViews.size());
    model.bufferViews.push_back(std::move(view));
    accessor.byteOffset = 0;
    accessor.componentType = componentType;
    accessor.normalized = false;
    accessor.sparse = {};
}

tinygltf::Accessor& accessorAt(tinygltf::Model& model, int index, const std::string& element) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
        fail(element, fmt::format("accessors[{}] does not exist", index));
    return model.accessors[index];
}

void decodePrimitive(tinygltf::Model& model, tinygltf::Primitive& primitive, const tinygltf::Value& ext,
                     const std::string& element) {
    if (!ext.IsObject()) fail(element, "is not an object");
    const tinygltf::Value& viewValue = ext.Get("bufferView");
    if (!viewValue.IsInt()) fail(element + ".bufferView", "missing or not an integer");
    const int viewIndex = viewValue.Get<int>();
    if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size())
        fail(element + ".bufferView", fmt::format("bufferViews[{}] does not exist", viewIndex));
    const tinygltf::BufferView& view = model.bufferViews[viewIndex];
    const std::string viewName = fmt::format("bufferViews[{}]", viewIndex);
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        fail(viewName, fmt::format("buffers[{}] does not exist", view.buffer));
    const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        fail(viewName, fmt::format("bytes [{}, {}) exceed buffers[{}] ({} bytes)", view.byteOffset,
                                   view.byteOffset + view.byteLength, view.buffer, data.size()));

    draco::DecoderBuffer stream;
    stream.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&stream);
    if (!decoded.ok()) fail(element, "the Draco stream does not decode: " + decoded.status().error_msg_string());
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh) fail(element, "the Draco stream holds no mesh");
    const size_t points = mesh->num_points();
    if (points > kMaxDecodedElements || size_t(mesh->num_faces()) * 3 > kMaxDecodedElements)
        fail(element, fmt::format("the Draco mesh has {} points and {} triangles, beyond the limit of {} elements",
                                  points, mesh->num_faces(), kMaxDecodedElements));

    const tinygltf::Value& attributes = ext.Get("attributes");
    if (!attributes.IsObject()) fail(element + ".attributes", "missing or not an object");
    for (const std::string& name : attributes.Keys()) {
        const std::string where = fmt::format("{}.attributes.{}", element, name);
        const tinygltf::Value& id = attributes.Get(name);
        if (!id.IsInt()) fail(where, "not an integer");
        const auto it = primitive.attributes.find(name);
        if (it == primitive.attributes.end()) fail(where, "names an attribute the primitive does not have");
        tinygltf::Accessor& accessor = accessorAt(model, it->second, where);
        const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(static_cast<uint32_t>(id.Get<int>()));
        if (!attribute) fail(where, fmt::format("the Draco stream has no attribute {}", id.Get<int>()));
        const int components = tinygltf::GetNumComponentsInType(accessor.type);
        if (components <= 0 || attribute->num_components() != components)
            fail(where, fmt::format("the Draco attribute has {} components, accessors[{}] {}",
                                    int(attribute->num_components()), it->second, components));
        if (accessor.count != points)
            fail(where, fmt::format("the Draco mesh has {} points, accessors[{}] count {}", points, it->second,
                                    accessor.count));
        std::vector<unsigned char> bytes(points * components * sizeof(float));
        float value[4] = {};
        for (size_t p = 0; p < points; ++p) {
            const draco::AttributeValueIndex index = attribute->mapped_index(draco::PointIndex(static_cast<uint32_t>(p)));
            if (index.value() >= attribute->size() ||
                !attribute->ConvertValue<float>(index, static_cast<int8_t>(components), value))
                fail(where, fmt::format("point {} does not decode", p));
            std::memcpy(bytes.data() + p * components * sizeof(float), value, components * sizeof(float));
        }
        attach(model, it->second, std::move(bytes), TINYGLTF_COMPONENT_TYPE_FLOAT);
    }

    if (primitive.indices >= 0) {
        const std::string where = element + " (indices)";
        tinygltf::Accessor& accessor = accessorAt(model, primitive.indices, where);
        const size_t count = size_t(mesh->num_faces()) * 3;
        if (accessor.count != count)
            fail(where, fmt::format("the Draco mesh has {} indices, accessors[{}] count {}", count, primitive.indices,
                                    accessor.count));
        std::vector<unsigned char> bytes(count * sizeof(uint32_t));
        for (uint32_t f = 0; f < mesh->num_faces(); ++f) {
            const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(f));
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = face[k].value();
                std::memcpy(bytes.data() + (size_t(f) * 3 + k) * sizeof(uint32_t), &v, sizeof(uint32_t));
            }
        }
        attach(model, primitive.indices, std::move(bytes), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    }
}

}  // namespace

void decodeDracoPrimitives(tinygltf::Model& model) {
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            const auto it = primitive.extensions.find(kExtension);
            if (it == primitive.extensions.end()) continue;
            decodePrimitive(model, primitive, it->second,
                            fmt::format("meshes[{}].primitives[{}].extensions.{}", m, p, kExtension));
        }
}

}  // namespace vkp
