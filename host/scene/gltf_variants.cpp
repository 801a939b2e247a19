#include "scene/gltf_variants.h"

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {
namespace {

constexpr const char* kExtension = "KHR_materials_variants";

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

bool isIndex(const tinygltf::Value& v) {
    return v.IsNumber() && v.GetNumberAsDouble() >= 0.0 && v.GetNumberAsDouble() <= 1.0e9 &&
           v.GetNumberAsDouble() == double(int(v.GetNumberAsDouble()));
}

}  // namespace

std::vector<std::string> materialVariantNames(const tinygltf::Model& model) {
    std::vector<std::string> names;
    const auto it = model.extensions.find(kExtension);
    if (it == model.extensions.end()) return names;
    const std::string element = fmt::format("extensions.{}.variants", kExtension);
    if (!it->second.IsObject() || !it->second.Has("variants") || !it->second.Get("variants").IsArray())
        fail(element, "needs an array of variants");
    const tinygltf::Value& variants = it->second.Get("variants");
    for (size_t i = 0; i < variants.ArrayLen(); ++i) {
        const tinygltf::Value& v = variants.Get(int(i));
        if (!v.IsObject()) fail(fmt::format("{}[{}]", element, i), "is not an object");
        if (v.Has("name") && !v.Get("name").IsString()) fail(fmt::format("{}[{}].name", element, i), "is not a string");
        names.push_back(v.Has("name") ? v.Get("name").Get<std::string>() : std::string());
    }
    return names;
}

int materialVariantIndex(const std::vector<std::string>& names, const std::string& name) {
    if (name.empty()) return -1;
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return int(i);
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw InputError(fmt::format("--variant {}: the file has no such material variant ({})", name,
                                 names.empty() ? "it has none" : "it has " + list));
}

int variantMaterial(const tinygltf::Primitive& primitive, int variant, size_t variantCount, const std::string& element) {
    const auto it = primitive.extensions.find(kExtension);
    if (it == primitive.extensions.end()) return primitive.material;
    const std::string mappingsName = fmt::format("{}.extensions.{}.mappings", element, kExtension);
    if (!it->second.IsObject() || !it->second.Has("mappings") || !it->second.Get("mappings").IsArray())
        fail(mappingsName, "needs an array of mappings");
    const tinygltf::Value& mappings = it->second.Get("mappings");
    int chosen = primitive.material;
    for (size_t m = 0; m < mappings.ArrayLen(); ++m) {
        const tinygltf::Value& mapping = mappings.Get(int(m));
        const std::string name = fmt::format("{}[{}]", mappingsName, m);
        if (!mapping.IsObject() || !mapping.Has("material") || !isIndex(mapping.Get("material")) ||
            !mapping.Has("variants") || !mapping.Get("variants").IsArray())
            fail(name, "needs a material index and an array of variant indices");
        for (size_t k = 0; k < mapping.Get("variants").ArrayLen(); ++k) {
            const tinygltf::Value& v = mapping.Get("variants").Get(int(k));
            if (!isIndex(v) || size_t(v.GetNumberAsDouble()) >= variantCount)
                fail(fmt::format("{}.variants[{}]", name, k),
                     fmt::format("is not one of the file's {} variant(s)", variantCount));
            if (int(v.GetNumberAsDouble()) == variant) chosen = int(mapping.Get("material").GetNumberAsDouble());
        }
    }
    return chosen;
}

std::vector<int> variantMaterials(const tinygltf::Primitive& primitive) {
    std::vector<int> materials;
    const auto it = primitive.extensions.find(kExtension);
    if (it == primitive.extensions.end() || !it->second.IsObject() || !it->second.Has("mappings")) return materials;
    const tinygltf::Value& mappings = it->second.Get("mappings");
    for (size_t m = 0; mappings.IsArray() && m < mappings.ArrayLen(); ++m) {
        const tinygltf::Value& mapping = mappings.Get(int(m));
        if (mapping.IsObject() && mapping.Has("material") && isIndex(mapping.Get("material")))
            materials.push_back(int(mapping.Get("material").GetNumberAsDouble()));
    }
    return materials;
}

}  // namespace vkp
