#include "scene/gltf_meshopt.h"

#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "util/errors.h"

namespace vkp {
namespace {

constexpr std::string_view kExtensions[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};
constexpr uint32_t kGlbMagic = 0x46546C67, kJsonChunk = 0x4E4F534A;

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

uint32_t readU32(const std::vector<unsigned char>& bytes, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

void writeU32(std::vector<unsigned char>& bytes, uint32_t v) {
    const size_t at = bytes.size();
    bytes.resize(at + 4);
    std::memcpy(bytes.data() + at, &v, 4);
}

const tinygltf::Value* meshoptExtension(const tinygltf::ExtensionMap& extensions, std::string* name) {
    for (const std::string_view e : kExtensions)
        if (const auto it = extensions.find(std::string(e)); it != extensions.end()) {
            *name = std::string(e);
            return &it->second;
        }
    return nullptr;
}

uint64_t sizeField(const tinygltf::Value& ext, const char* key, const std::string& element, bool required) {
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsNumber()) {
        if (required || v.Type() != tinygltf::NULL_TYPE) fail(element + "." + key, "missing or not a number");
        return 0;
    }
    const double d = v.GetNumberAsDouble();
    if (!(d >= 0.0 && d <= 9.0e15) || d != double(uint64_t(d))) fail(element + "." + key, "not a non-negative integer");
    return uint64_t(d);
}

std::string stringField(const tinygltf::Value& ext, const char* key, const char* fallback, const std::string& element) {
    const tinygltf::Value& v = ext.Get(key);
    if (v.Type() == tinygltf::NULL_TYPE) return fallback;
    if (!v.IsString()) fail(element + "." + key, "not a string");
    return v.Get<std::string>();
}

void decodeView(tinygltf::Model& model, tinygltf::BufferView& view, const tinygltf::Value& ext,
                const std::string& element) {
    if (!ext.IsObject()) fail(element, "is not an object");
    const uint64_t source = sizeField(ext, "buffer", element, true);
    const uint64_t offset = sizeField(ext, "byteOffset", element, false);
    const uint64_t length = sizeField(ext, "byteLength", element, true);
    const uint64_t stride = sizeField(ext, "byteStride", element, true);
    const uint64_t count = sizeField(ext, "count", element, true);
    const std::string mode = stringField(ext, "mode", "", element);
    const std::string filter = stringField(ext, "filter", "NONE", element);
    if (source >= model.buffers.size()) fail(element + ".buffer", fmt::format("buffers[{}] does not exist", source));
    const std::vector<unsigned char>& in = model.buffers[source].data;
    if (offset > in.size() || length > in.size() - offset)
        fail(element, fmt::format("compressed bytes [{}, {}) exceed buffers[{}] ({} bytes)", offset, offset + length,
                                  source, in.size()));
    if (stride == 0 || stride > 256 || count > (uint64_t(1) << 28))
        fail(element, fmt::format("byteStride {} or count {} is out of range", stride, count));
    const uint64_t size = stride * count;
    if (size > view.byteLength)
        fail(element, fmt::format("count {} x byteStride {} exceeds the bufferView's byteLength {}", count, stride,
                                  view.byteLength));
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        fail(element, fmt::format("buffers[{}] does not exist", view.buffer));
    std::vector<unsigned char>& out = model.buffers[view.buffer].data;
    if (view.byteOffset > out.size() || size > out.size() - view.byteOffset)
        fail(element, fmt::format("bytes [{}, {}) exceed buffers[{}] ({} bytes)", view.byteOffset,
                                  view.byteOffset + size, view.buffer, out.size()));

    std::vector<unsigned char> decoded(size);
    const unsigned char* stream = in.data() + offset;
    int rc = 0;
    if (mode == "ATTRIBUTES") {
        if (stride % 4 != 0) fail(element, fmt::format("ATTRIBUTES need a byteStride multiple of 4, not {}", stride));
        rc = meshopt_decodeVertexBuffer(decoded.data(), count, stride, stream, length);
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4) fail(element, fmt::format("{} need a byteStride of 2 or 4, not {}", mode, stride));
        if (mode == "TRIANGLES" && count % 3 != 0) fail(element, fmt::format("TRIANGLES count {} is not a multiple of 3", count));
        rc = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(decoded.data(), count, stride, stream, length)
                                 : meshopt_decodeIndexSequence(decoded.data(), count, stride, stream, length);
    } else {
        fail(element + ".mode", fmt::format("\"{}\" is not ATTRIBUTES, TRIANGLES or INDICES", mode));
    }
    if (rc != 0) fail(element, fmt::format("the {} stream does not decode (meshoptimizer error {})", mode, rc));

    if (filter != "NONE" && mode != "ATTRIBUTES") fail(element + ".filter", "filters apply to ATTRIBUTES only");
    if (filter == "OCTAHEDRAL") {
        if (stride != 4 && stride != 8) fail(element, "OCTAHEDRAL needs a byteStride of 4 or 8");
        meshopt_decodeFilterOct(decoded.data(), count, stride);
    } else if (filter == "QUATERNION") {
        if (stride != 8) fail(element, "QUATERNION needs a byteStride of 8");
        meshopt_decodeFilterQuat(decoded.data(), count, stride);
    } else if (filter == "EXPONENTIAL") {
        meshopt_decodeFilterExp(decoded.data(), count, stride);  // stride % 4 == 0 checked above
    } else if (filter != "NONE") {
        fail(element + ".filter", fmt::format("\"{}\" is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL", filter));
    }
    std::memcpy(out.data() + view.byteOffset, decoded.data(), size);
}

}  // namespace

MeshoptFallbacks prepareMeshoptFallbacks(GltfDocument& document) {
    std::vector<unsigned char>& bytes = document.bytes;
    size_t jsonStart = 0, jsonLength = bytes.size();
    if (document.binary) {  // the preflight checked the container
        jsonLength = readU32(bytes, 12);
        jsonStart = 20;
    }
    std::string_view json(reinterpret_cast<const char*>(bytes.data()) + jsonStart, jsonLength);
    while (!json.empty() && json.back() == '\0') json.remove_suffix(1);  // padding some exporters use
    const bool meshopt = json.find("meshopt_compression") != std::string_view::npos;
    const bool draco = json.find("KHR_draco_mesh_compression") != std::string_view::npos;
    if (!meshopt && !draco) return {};
    nlohmann::json root = nlohmann::json::parse(json);
    MeshoptFallbacks fallbacks;
    bool changed = false;
    // tinygltf refuses an index accessor without a bufferView, as a Draco primitive's is: it gets
    // the Draco stream's view as a placeholder until decodeDracoPrimitives() replaces it.
    if (draco && root.contains("meshes") && root["meshes"].is_array() && root.contains("accessors") &&
        root["accessors"].is_array())
        for (size_t m = 0; m < root["meshes"].size(); ++m) {
            nlohmann::json& mesh = root["meshes"][m];
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
            for (size_t p = 0; p < mesh["primitives"].size(); ++p) {
                nlohmann::json& primitive = mesh["primitives"][p];
                if (!primitive.is_object() || !primitive.contains("indices") || !primitive.contains("extensions")) continue;
                const nlohmann::json& extensions = primitive["extensions"];
                if (!extensions.is_object() || !extensions.contains("KHR_draco_mesh_compression")) continue;
                const nlohmann::json& ext = extensions["KHR_draco_mesh_compression"];
                const nlohmann::json& indices = primitive["indices"];
                if (!ext.is_object() || !ext.contains("bufferView") || !ext["bufferView"].is_number_unsigned() ||
                    !indices.is_number_unsigned() || indices.get<uint64_t>() >= root["accessors"].size())
                    continue;  // decodeDracoPrimitives() names the error
                const size_t view = ext["bufferView"].get<size_t>();
                const size_t views = root.contains("bufferViews") && root["bufferViews"].is_array() ? root["bufferViews"].size() : 0;
                if (view >= views)
                    fail(fmt::format("meshes[{}].primitives[{}].extensions.KHR_draco_mesh_compression.bufferView", m, p),
                         fmt::format("bufferViews[{}] does not exist", view));
                nlohmann::json& accessor = root["accessors"][indices.get<size_t>()];
                if (accessor.is_object() && !accessor.contains("bufferView")) {
                    accessor["bufferView"] = ext["bufferView"];
                    changed = true;
                }
            }
        }
    nlohmann::json none = nlohmann::json::array();
    nlohmann::json& buffers = root.contains("buffers") ? root["buffers"] : none;
    for (size_t i = 0; meshopt && buffers.is_array() && i < buffers.size(); ++i) {
        nlohmann::json& buffer = buffers[i];
        if (!buffer.is_object() || buffer.contains("uri") || (document.binary && i == 0)) continue;
        if (!buffer.contains("extensions") || !buffer["extensions"].is_object()) continue;
        bool isFallback = false;
        for (const std::string_view e : kExtensions) isFallback |= buffer["extensions"].contains(std::string(e));
        if (!isFallback) continue;
        fallbacks[int(i)] = buffer["byteLength"].get<uint64_t>();  // the preflight checked it
        buffer["byteLength"] = 1;
        buffer["uri"] = "data:application/octet-stream;base64,AA==";
    }
    if (fallbacks.empty() && !changed) return {};
    std::string text = root.dump();
    if (!document.binary) {
        bytes.assign(text.begin(), text.end());
        return fallbacks;
    }
    while (text.size() % 4 != 0) text.push_back(' ');
    std::vector<unsigned char> glb;
    writeU32(glb, kGlbMagic);
    writeU32(glb, 2);
    writeU32(glb, 0);  // total length, below
    writeU32(glb, static_cast<uint32_t>(text.size()));
    writeU32(glb, kJsonChunk);
    glb.insert(glb.end(), text.begin(), text.end());
    const size_t rest = 20 + jsonLength;  // the BIN chunk, if any
    if (rest < bytes.size()) glb.insert(glb.end(), bytes.begin() + rest, bytes.end());
    const uint32_t total = static_cast<uint32_t>(glb.size());
    std::memcpy(glb.data() + 8, &total, 4);
    bytes = std::move(glb);
    return fallbacks;
}

void decodeMeshoptViews(tinygltf::Model& model, const MeshoptFallbacks& fallbacks) {
    for (const auto& [index, length] : fallbacks)
        if (static_cast<size_t>(index) < model.buffers.size()) model.buffers[index].data.assign(length, 0);
    for (size_t i = 0; i < model.bufferViews.size(); ++i) {
        std::string name;
        if (const tinygltf::Value* ext = meshoptExtension(model.bufferViews[i].extensions, &name))
            decodeView(model, model.bufferViews[i], *ext, fmt::format("bufferViews[{}].extensions.{}", i, name));
    }
}

}  // namespace vkp
