// glTF materials (metallic-roughness plus the supported KHR_materials_* extensions) and their
// textures -> vkp::Material and vkp::Texture.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkp {

class GltfMaterials {
public:
    using Warn = std::function<void(const std::string&)>;

    // Appends to scene.materials and scene.textures; `warn` gets "ELEMENT: message" lines.
    GltfMaterials(const tinygltf::Model& model, Scene& scene, Warn warn);

    // Converts every material of the file, so material i of the file is Scene::materials[i].
    void convertAll();

    // The glTF default material (base colour 1, metallic 1, roughness 1), appended on first use.
    uint32_t defaultMaterial();

private:
    Material convert(int index);
    void readExtensions(const tinygltf::Material& source, const std::string& element, Material& material);
    void validate(const std::string& element, Material& material);
    // A material texture reference -> an index into Scene::textureViews (-1 without a texture):
    // the image (decoded once per colour space), the texCoord set, KHR_texture_transform and the
    // sampler. Every material texture goes through here.
    int texture(int gltfTexture, int texCoord, const tinygltf::ExtensionMap& extensions, bool srgb,
                     const std::string& element);
    void readSampler(int gltfTexture, TextureView& view);
    void readTransform(const tinygltf::Value& transform, const std::string& element, TextureView& view);
    // A textureInfo object `key` of an extension object (KHR_materials_*), or -1 when absent.
    int extensionTexture(const tinygltf::Value& object, const char* key, bool srgb, const std::string& element);
    double textureScale(const tinygltf::Value& object, const char* key, const std::string& element);
    // KHR_materials_pbrSpecularGlossiness and KHR_materials_unlit, converted to what the
    // metallic-roughness material renders (docs/scene-format.md, "Materials").
    void readSpecularGlossiness(const tinygltf::Value& extension, const std::string& element, Material& material);
    void applyUnlit(Material& material);
    // A metallic-roughness texture (G = 1 - glossinessFactor x A of the view's image, B = 0) for
    // a specularGlossinessTexture view: one image per (image, factor).
    int roughnessFromGlossiness(int view, float glossinessFactor);
    Texture convertImage(int source, bool srgb);

    const tinygltf::Model& m_model;
    Scene& m_scene;
    Warn m_warn;
    std::map<std::pair<int, bool>, int> m_textureOf;  // (image, srgb) -> Scene::textures index
    std::map<TextureView, int> m_viewOf;              // -> Scene::textureViews index
    std::map<std::pair<int, float>, int> m_roughnessOf;  // (image, glossinessFactor) -> Scene::textures index
    int m_default = -1;
};

}  // namespace vkp
