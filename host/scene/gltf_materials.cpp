#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>

#include <fmt/format.h>

#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace vkp {
namespace {

// TEXCOORD_n: any n (the loader maps the sets the textures read to the device's two per
// triangle, gltf_loader.cpp remapTexCoordSets); this only bounds nonsense.
constexpr int kMaxTexCoordSet = 1 << 20;

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name) {
    const auto it = extensions.find(name);
    return it == extensions.end() ? nullptr : &it->second;
}

// A number of an extension object, or `fallback` when absent.
double numberOr(const tinygltf::Value& object, const char* key, double fallback, const std::string& element) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& value = object.Get(key);
    if (!value.IsNumber()) fail(fmt::format("{}.{}", element, key), "not a number");
    return value.GetNumberAsDouble();
}

glm::vec3 vec3Or(const tinygltf::Value& object, const char* key, glm::vec3 fallback, const std::string& element) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& value = object.Get(key);
    if (!value.IsArray() || value.ArrayLen() != 3) fail(fmt::format("{}.{}", element, key), "needs 3 numbers");
    glm::vec3 v;
    for (int k = 0; k < 3; ++k) {
        if (!value.Get(k).IsNumber()) fail(fmt::format("{}.{}", element, key), "needs 3 numbers");
        v[k] = static_cast<float>(value.Get(k).GetNumberAsDouble());
    }
    return v;
}

// 16-bit channels arrive in host order from stb; round to the nearest 8-bit value.
uint8_t channel(const std::vector<unsigned char>& data, size_t at, bool sixteenBit) {
    if (!sixteenBit) return data[at];
    uint16_t v;
    std::memcpy(&v, data.data() + at * 2, 2);
    return static_cast<uint8_t>((uint32_t(v) * 255 + 32767) / 65535);
}

}  // namespace

bool TextureView::operator<(const TextureView& o) const {
    const auto key = [](const TextureView& v) {
        return std::make_tuple(v.image, v.texCoord, v.uvRow0.x, v.uvRow0.y, v.uvRow0.z, v.uvRow1.x, v.uvRow1.y,
                               v.uvRow1.z, uint32_t(v.wrapS), uint32_t(v.wrapT), v.nearest, v.minNearest,
                               uint32_t(v.mipmaps));
    };
    return key(*this) < key(o);
}

GltfMaterials::GltfMaterials(const tinygltf::Model& model, Scene& scene, Warn warn)
    : m_model(model), m_scene(scene), m_warn(std::move(warn)) {}

void GltfMaterials::convertAll() {
    for (size_t i = 0; i < m_model.materials.size(); ++i) m_scene.materials.push_back(convert(static_cast<int>(i)));
}

uint32_t GltfMaterials::defaultMaterial() {
    if (m_default < 0) {
        m_default = static_cast<int>(m_scene.materials.size());
        Material material;  // vkp::Material's defaults are glTF's
        material.name = "default";
        m_scene.materials.push_back(material);
    }
    return static_cast<uint32_t>(m_default);
}

Material GltfMaterials::convert(int index) {
    const tinygltf::Material& source = m_model.materials[index];
    const std::string element = fmt::format("materials[{}]", index);
    const auto& pbr = source.pbrMetallicRoughness;
    Material m;
    m.name = source.name.empty() ? element : source.name;
    if (pbr.baseColorFactor.size() != 4) fail(element + ".pbrMetallicRoughness.baseColorFactor", "needs 4 numbers");
    m.baseColor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
    m.metallic = static_cast<float>(pbr.metallicFactor);
    m.roughness = static_cast<float>(pbr.roughnessFactor);
    if (source.emissiveFactor.size() != 3) fail(element + ".emissiveFactor", "needs 3 numbers");
    m.emissive = glm::vec3(source.emissiveFactor[0], source.emissiveFactor[1], source.emissiveFactor[2]);
    m.doubleSided = source.doubleSided;
    const std::string pbrName = element + ".pbrMetallicRoughness";
    m.baseColorTexture = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                 pbr.baseColorTexture.extensions, true, pbrName + ".baseColorTexture");
    m.metallicRoughnessTexture = texture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                                         pbr.metallicRoughnessTexture.extensions, false,
                                         pbrName + ".metallicRoughnessTexture");
    m.emissiveTexture = texture(source.emissiveTexture.index, source.emissiveTexture.texCoord,
                                source.emissiveTexture.extensions, true, element + ".emissiveTexture");
    m.normalTexture = texture(source.normalTexture.index, source.normalTexture.texCoord,
                              source.normalTexture.extensions, false, element + ".normalTexture");
    m.normalScale = static_cast<float>(source.normalTexture.scale);
    if (!std::isfinite(m.normalScale) || std::abs(m.normalScale) > 1.0e6f)
        fail(element + ".normalTexture.scale", "must be a finite number");
    if (source.alphaMode == "MASK") m.alphaMode = AlphaMode::Mask;
    else if (source.alphaMode == "BLEND") m.alphaMode = AlphaMode::Blend;
    else if (source.alphaMode != "OPAQUE" && !source.alphaMode.empty())
        fail(element + ".alphaMode", fmt::format("\"{}\" is not OPAQUE, MASK or BLEND", source.alphaMode));
    m.alphaCutoff = static_cast<float>(source.alphaCutoff);
    if (!(m.alphaCutoff >= 0.0f) || !std::isfinite(m.alphaCutoff))
        fail(element + ".alphaCutoff", fmt::format("{} is not a non-negative number", source.alphaCutoff));
    readExtensions(source, element, m);
    validate(element, m);
    // After validate: the base colour it clamped becomes the emission.
    if (extension(source.extensions, "KHR_materials_unlit")) applyUnlit(m);
    return m;
}

// KHR_materials_pbrSpecularGlossiness by the conversion the Khronos extensions give for it
// (KHR_materials_specular's and KHR_materials_ior's "specular-glossiness" notes): base colour =
// diffuse, metallic 0, roughness = 1 - glossiness, KHR_materials_specular with specularColor =
// the specular colour (factor x texture RGB) and specularFactor 1, and KHR_materials_ior's ior 0
// (an infinite index: the specular reflectance is the specular colour in every direction). The
// extension overrides pbrMetallicRoughness, which is its fallback for viewers without it.
void GltfMaterials::readSpecularGlossiness(const tinygltf::Value& e, const std::string& element, Material& m) {
    m.baseColor = glm::vec4(1.0f);
    if (e.IsObject() && e.Has("diffuseFactor")) {
        const tinygltf::Value& v = e.Get("diffuseFactor");
        if (!v.IsArray() || v.ArrayLen() != 4) fail(element + ".diffuseFactor", "needs 4 numbers");
        for (int k = 0; k < 4; ++k) {
            if (!v.Get(k).IsNumber()) fail(element + ".diffuseFactor", "needs 4 numbers");
            m.baseColor[k] = static_cast<float>(v.Get(k).GetNumberAsDouble());
        }
    }
    m.baseColorTexture = extensionTexture(e, "diffuseTexture", true, element);
    m.metallic = 0.0f;
    m.metallicRoughnessTexture = -1;
    m.specular = 1.0f;
    m.specularTexture = -1;
    m.specularColor = vec3Or(e, "specularFactor", glm::vec3(1.0f), element);
    m.ior = 0.0f;
    const double glossiness = numberOr(e, "glossinessFactor", 1.0, element);
    if (!(glossiness >= 0.0 && glossiness <= 1.0))
        fail(element + ".glossinessFactor", fmt::format("{} is not within [0, 1]", glossiness));
    m.roughness = static_cast<float>(1.0 - glossiness);
    // The texture's RGB (sRGB) is the specular colour, its A (linear) the glossiness.
    m.specularColorTexture = extensionTexture(e, "specularGlossinessTexture", true, element);
    if (m.specularColorTexture >= 0) {
        m.metallicRoughnessTexture = roughnessFromGlossiness(m.specularColorTexture, static_cast<float>(glossiness));
        m.roughness = 1.0f;  // the baked texture holds 1 - glossinessFactor x A
    }
}

int GltfMaterials::roughnessFromGlossiness(int viewIndex, float glossinessFactor) {
    TextureView view = m_scene.textureViews[viewIndex];
    const auto key = std::make_pair(view.image, glossinessFactor);
    if (const auto it = m_roughnessOf.find(key); it != m_roughnessOf.end()) {
        view.image = it->second;
    } else {
        const Texture& source = m_scene.textures[view.image];
        Texture t;
        t.name = source.name + " (roughness = 1 - glossiness)";
        t.width = source.width;
        t.height = source.height;
        t.srgb = false;
        t.rgba8.resize(source.rgba8.size());
        for (size_t i = 0; i < t.rgba8.size(); ++i) {
            const float gloss = glossinessFactor * float(source.rgba8[i] >> 24) / 255.0f;
            const auto roughness = static_cast<uint32_t>(std::lround(255.0f * (1.0f - gloss)));
            t.rgba8[i] = (roughness << 8) | 0xff000000u;  // R (occlusion) 0, G roughness, B (metallic) 0, A 1
        }
        view.image = static_cast<int>(m_scene.textures.size());
        m_scene.textures.push_back(std::move(t));
        m_roughnessOf[key] = view.image;
    }
    if (const auto it = m_viewOf.find(view); it != m_viewOf.end()) return it->second;
    const int index = static_cast<int>(m_scene.textureViews.size());
    m_scene.textureViews.push_back(view);
    m_viewOf[view] = index;
    return index;
}

// KHR_materials_unlit: the surface shows its base colour (factor x texture) and is not lit. As a
// radiometric material: it emits radiance = base colour (the base colour texture becomes the
// emissive texture, sRGB as before) and reflects and transmits nothing (black base colour, no
// specular, coat, sheen or transmission); alpha (MASK, BLEND) is kept. So every ray that reaches
// it, the camera's and bounced ones, sees the base colour, and, being an emitter, it lights what
// is around it like any emissive surface (a rasterizer's unlit surface lights nothing). COLOR_0
// does not multiply emission in vkphoton, so an unlit surface ignores vertex colours.
void GltfMaterials::applyUnlit(Material& m) {
    m.emissive = glm::vec3(m.baseColor);
    m.emissiveTexture = m.baseColorTexture;
    m.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, m.baseColor.w);  // the texture's alpha still cuts out
    m.metallic = 0.0f;
    m.metallicRoughnessTexture = -1;
    m.specular = 0.0f;
    m.specularTexture = -1;
    m.transmission = 0.0f;
    m.transmissionTexture = -1;
    m.clearcoat = 0.0f;
    m.sheenColor = glm::vec3(0.0f);
    m.normalTexture = -1;
}

void GltfMaterials::readExtensions(const tinygltf::Material& source, const std::string& element, Material& m) {
    const auto name = [&](const char* ext) { return fmt::format("{}.extensions.{}", element, ext); };
    if (const auto* e = extension(source.extensions, "KHR_materials_emissive_strength"))
        m.emissive *= static_cast<float>(numberOr(*e, "emissiveStrength", 1.0, name("KHR_materials_emissive_strength")));
    if (const auto* e = extension(source.extensions, "KHR_materials_transmission")) {
        const std::string transmission = name("KHR_materials_transmission");
        m.transmission = static_cast<float>(numberOr(*e, "transmissionFactor", 0.0, transmission));
        m.transmissionTexture = extensionTexture(*e, "transmissionTexture", false, transmission);
    }
    if (const auto* e = extension(source.extensions, "KHR_materials_ior"))
        m.ior = static_cast<float>(numberOr(*e, "ior", 1.5, name("KHR_materials_ior")));
    if (const auto* e = extension(source.extensions, "KHR_materials_specular")) {
        const std::string specular = name("KHR_materials_specular");
        m.specular = static_cast<float>(numberOr(*e, "specularFactor", 1.0, specular));
        m.specularColor = vec3Or(*e, "specularColorFactor", glm::vec3(1.0f), specular);
        m.specularTexture = extensionTexture(*e, "specularTexture", false, specular);
        m.specularColorTexture = extensionTexture(*e, "specularColorTexture", true, specular);
    }
    if (const auto* e = extension(source.extensions, "KHR_materials_clearcoat")) {
        const std::string coat = name("KHR_materials_clearcoat");
        m.clearcoat = static_cast<float>(numberOr(*e, "clearcoatFactor", 0.0, coat));
        m.clearcoatRoughness = static_cast<float>(numberOr(*e, "clearcoatRoughnessFactor", 0.0, coat));
        m.clearcoatTexture = extensionTexture(*e, "clearcoatTexture", false, coat);
        m.clearcoatRoughnessTexture = extensionTexture(*e, "clearcoatRoughnessTexture", false, coat);
        m.clearcoatNormalTexture = extensionTexture(*e, "clearcoatNormalTexture", false, coat);
        m.clearcoatNormalScale = static_cast<float>(textureScale(*e, "clearcoatNormalTexture", coat));
    }
    if (const auto* e = extension(source.extensions, "KHR_materials_sheen")) {
        const std::string sheen = name("KHR_materials_sheen");
        m.sheenColor = vec3Or(*e, "sheenColorFactor", glm::vec3(0.0f), sheen);
        m.sheenRoughness = static_cast<float>(numberOr(*e, "sheenRoughnessFactor", 0.0, sheen));
        m.sheenColorTexture = extensionTexture(*e, "sheenColorTexture", true, sheen);
        m.sheenRoughnessTexture = extensionTexture(*e, "sheenRoughnessTexture", false, sheen);
    }
    if (const auto* e = extension(source.extensions, "KHR_materials_pbrSpecularGlossiness"))
        readSpecularGlossiness(*e, name("KHR_materials_pbrSpecularGlossiness"), m);
    if (const auto* e = extension(source.extensions, "KHR_materials_anisotropy")) {
        const std::string anisotropy = name("KHR_materials_anisotropy");
        m.anisotropy = static_cast<float>(numberOr(*e, "anisotropyStrength", 0.0, anisotropy));
        m.anisotropyRotation = static_cast<float>(numberOr(*e, "anisotropyRotation", 0.0, anisotropy));
        m.anisotropyTexture = extensionTexture(*e, "anisotropyTexture", false, anisotropy);
        if (!std::isfinite(m.anisotropyRotation) || std::abs(m.anisotropyRotation) > 1.0e6f)
            fail(anisotropy + ".anisotropyRotation", "must be a finite number");
    }
    if (const auto* e = extension(source.extensions, "KHR_materials_iridescence")) {
        const std::string iridescence = name("KHR_materials_iridescence");
        m.iridescence = static_cast<float>(numberOr(*e, "iridescenceFactor", 0.0, iridescence));
        m.iridescenceIor = static_cast<float>(numberOr(*e, "iridescenceIor", 1.3, iridescence));
        m.iridescenceThicknessMin = static_cast<float>(numberOr(*e, "iridescenceThicknessMinimum", 100.0, iridescence));
        m.iridescenceThicknessMax = static_cast<float>(numberOr(*e, "iridescenceThicknessMaximum", 400.0, iridescence));
        m.iridescenceTexture = extensionTexture(*e, "iridescenceTexture", false, iridescence);
        m.iridescenceThicknessTexture = extensionTexture(*e, "iridescenceThicknessTexture", false, iridescence);
        if (m.iridescenceIor < 1.0f) fail(iridescence + ".iridescenceIor", fmt::format("{} is below 1", m.iridescenceIor));
    }
    if (const auto* e = extension(source.extensions, "KHR_materials_dispersion"))
        m.dispersion = static_cast<float>(numberOr(*e, "dispersion", 0.0, name("KHR_materials_dispersion")));
    if (const auto* e = extension(source.extensions, "KHR_materials_volume")) {
        const std::string volume = name("KHR_materials_volume");
        m.thickness = static_cast<float>(numberOr(*e, "thicknessFactor", 0.0, volume));
        m.attenuationDistance = static_cast<float>(numberOr(*e, "attenuationDistance", INFINITY, volume));
        m.attenuationColor = vec3Or(*e, "attenuationColor", glm::vec3(1.0f), volume);
    }
}

// Non-finite or negative factors are refused; factors the spec bounds by 1 are clamped (with a
// warning) because exporters write 1.0000001.
void GltfMaterials::validate(const std::string& element, Material& m) {
    const float values[] = {m.baseColor.x, m.baseColor.y, m.baseColor.z, m.baseColor.w, m.metallic, m.roughness,
                            m.emissive.x,  m.emissive.y,  m.emissive.z,  m.transmission, m.ior, m.thickness,
                            m.attenuationColor.x, m.attenuationColor.y, m.attenuationColor.z,
                            m.specular, m.specularColor.x, m.specularColor.y, m.specularColor.z,
                            m.sheenColor.x, m.sheenColor.y, m.sheenColor.z, m.sheenRoughness,
                            m.clearcoat, m.clearcoatRoughness, m.anisotropy, m.iridescence, m.iridescenceIor,
                            m.iridescenceThicknessMin, m.iridescenceThicknessMax, m.dispersion};
    for (const float v : values)
        if (!std::isfinite(v) || v < 0.0f) fail(element, "material factors must be finite and non-negative");
    if (glm::any(glm::greaterThan(m.emissive, glm::vec3(float(kMaxRadiometric)))))
        fail(element, fmt::format("emission {:.3g} W/m^2/sr (emissiveFactor x emissiveStrength) is beyond the {:g} vkphoton handles",
                                  std::max({m.emissive.x, m.emissive.y, m.emissive.z}), kMaxRadiometric));
    if (!(m.attenuationDistance > 0.0f)) fail(element + ".extensions.KHR_materials_volume.attenuationDistance", "must be positive");
    if (m.ior != 0.0f && m.ior < 1.0f) fail(element + ".extensions.KHR_materials_ior.ior", fmt::format("{} is below 1", m.ior));
    // ior 0 stays 0: KHR_materials_ior's specular-glossiness compatibility mode (an infinite ior:
    // the Fresnel term is 1 in every direction), which shared/bsdf.glsl evaluates.
    bool clamped = false;
    const auto clampUnit = [&](float& v) {
        clamped = clamped || v > 1.0f;
        v = std::min(v, 1.0f);
    };
    for (int k = 0; k < 4; ++k) clampUnit(m.baseColor[k]);
    for (int k = 0; k < 3; ++k) clampUnit(m.attenuationColor[k]);
    clampUnit(m.metallic);
    clampUnit(m.roughness);
    clampUnit(m.transmission);
    clampUnit(m.specular);
    for (int k = 0; k < 3; ++k) clampUnit(m.sheenColor[k]);
    clampUnit(m.sheenRoughness);
    clampUnit(m.clearcoat);
    clampUnit(m.clearcoatRoughness);
    clampUnit(m.anisotropy);
    clampUnit(m.iridescence);
    if (clamped)
        m_warn(element + ": factors above 1 (base colour, metallic, roughness, transmission, attenuation colour, specular, "
                         "sheen, clearcoat, anisotropy, iridescence) clamped to 1");
}

int GltfMaterials::extensionTexture(const tinygltf::Value& object, const char* key, bool srgb,
                                    const std::string& element) {
    if (!object.IsObject() || !object.Has(key)) return -1;
    const tinygltf::Value& info = object.Get(key);
    const std::string name = fmt::format("{}.{}", element, key);
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsNumber()) fail(name, "needs a texture index");
    const double index = info.Get("index").GetNumberAsDouble();
    if (index < 0.0 || index != std::floor(index) || index > 1.0e9) fail(name + ".index", "must be a non-negative integer");
    int texCoord = 0;
    if (info.Has("texCoord")) {
        const tinygltf::Value& t = info.Get("texCoord");
        if (!t.IsNumber() || t.GetNumberAsDouble() < 0.0 || t.GetNumberAsDouble() > 1.0e9) fail(name + ".texCoord", "must be a non-negative integer");
        texCoord = static_cast<int>(t.GetNumberAsDouble());
    }
    tinygltf::ExtensionMap extensions;
    if (info.Has("extensions") && info.Get("extensions").IsObject())
        for (const std::string& k : info.Get("extensions").Keys()) extensions[k] = info.Get("extensions").Get(k);
    return texture(static_cast<int>(index), texCoord, extensions, srgb, name);
}

// A normalTextureInfo's `scale` inside an extension object (1 when absent).
double GltfMaterials::textureScale(const tinygltf::Value& object, const char* key, const std::string& element) {
    if (!object.IsObject() || !object.Has(key)) return 1.0;
    const tinygltf::Value& info = object.Get(key);
    const std::string name = fmt::format("{}.{}", element, key);
    if (!info.IsObject() || !info.Has("scale")) return 1.0;
    const tinygltf::Value& scale = info.Get("scale");
    if (!scale.IsNumber() || !std::isfinite(scale.GetNumberAsDouble()) || std::abs(scale.GetNumberAsDouble()) > 1.0e6)
        fail(name + ".scale", "must be a finite number");
    return scale.GetNumberAsDouble();
}

int GltfMaterials::texture(int gltfTexture, int texCoord, const tinygltf::ExtensionMap& extensions, bool srgb,
                           const std::string& element) {
    if (gltfTexture < 0) return -1;
    if (static_cast<size_t>(gltfTexture) >= m_model.textures.size())
        fail(element, fmt::format("textures[{}] does not exist", gltfTexture));
    // EXT_texture_webp: the WebP image is preferred; `source` is the fallback for viewers without it.
    int source = m_model.textures[gltfTexture].source;
    if (const auto* webp = extension(m_model.textures[gltfTexture].extensions, "EXT_texture_webp")) {
        if (!webp->IsObject() || !webp->Has("source") || !webp->Get("source").IsNumber())
            fail(fmt::format("textures[{}].extensions.EXT_texture_webp", gltfTexture), "needs a source image index");
        const double index = webp->Get("source").GetNumberAsDouble();
        source = index >= 0.0 && index <= 1.0e9 && index == std::floor(index) ? int(index) : -1;
    }
    if (source < 0 || static_cast<size_t>(source) >= m_model.images.size())
        fail(fmt::format("textures[{}]", gltfTexture), "has no source image");
    TextureView view;
    view.texCoord = texCoord;
    if (const auto* e = extension(extensions, "KHR_texture_transform"))
        readTransform(*e, element + ".extensions.KHR_texture_transform", view);
    if (view.texCoord < 0 || view.texCoord > kMaxTexCoordSet)
        fail(element + ".texCoord", fmt::format("{} is not a TEXCOORD set (0 to {})", view.texCoord,
                                                kMaxTexCoordSet));
    readSampler(gltfTexture, view);
    const auto key = std::make_pair(source, srgb);
    if (const auto it = m_textureOf.find(key); it != m_textureOf.end()) {
        view.image = it->second;
    } else {
        view.image = static_cast<int>(m_scene.textures.size());
        m_scene.textures.push_back(convertImage(source, srgb));
        m_textureOf[key] = view.image;
    }
    if (const auto it = m_viewOf.find(view); it != m_viewOf.end()) return it->second;
    const int index = static_cast<int>(m_scene.textureViews.size());
    m_scene.textureViews.push_back(view);
    m_viewOf[view] = index;
    return index;
}

// glTF samplers: wrapS/wrapT 33071 (clamp), 33648 (mirrored repeat), 10497 (repeat, the
// default); magFilter 9728 NEAREST, else bilinear; minFilter: the filter within a mipmap level
// (NEAREST*: nearest texel, LINEAR*: bilinear) and between levels (none for NEAREST/LINEAR); left
// out, LINEAR_MIPMAP_LINEAR (trilinear), the spec leaving the choice to the renderer.
void GltfMaterials::readSampler(int gltfTexture, TextureView& view) {
    const int index = m_model.textures[gltfTexture].sampler;
    if (index < 0) return;
    const std::string element = fmt::format("samplers[{}]", index);
    if (static_cast<size_t>(index) >= m_model.samplers.size()) fail(element, "does not exist");
    const tinygltf::Sampler& sampler = m_model.samplers[index];
    const auto wrap = [&](int mode, const char* key) {
        switch (mode) {
        case -1:
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
        default: fail(fmt::format("{}.{}", element, key), fmt::format("{} is not 33071, 33648 or 10497", mode));
        }
    };
    view.wrapS = wrap(sampler.wrapS, "wrapS");
    view.wrapT = wrap(sampler.wrapT, "wrapT");
    if (sampler.magFilter != -1 && sampler.magFilter != TINYGLTF_TEXTURE_FILTER_NEAREST &&
        sampler.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR)
        fail(element + ".magFilter", fmt::format("{} is not 9728 (NEAREST) or 9729 (LINEAR)", sampler.magFilter));
    view.nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    switch (sampler.minFilter) {
    case -1:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: view.minNearest = false; view.mipmaps = MipmapMode::Linear; break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: view.minNearest = true; view.mipmaps = MipmapMode::None; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: view.minNearest = false; view.mipmaps = MipmapMode::None; break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: view.minNearest = true; view.mipmaps = MipmapMode::Nearest; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: view.minNearest = false; view.mipmaps = MipmapMode::Nearest; break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: view.minNearest = true; view.mipmaps = MipmapMode::Linear; break;
    default:
        fail(element + ".minFilter",
             fmt::format("{} is not 9728, 9729, 9984, 9985, 9986 or 9987 (NEAREST, LINEAR, *_MIPMAP_*)", sampler.minFilter));
    }
}

// KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) (u, v, 1) with R's rows (cos, sin)
// and (-sin, cos) (the extension's GLSL matrix read row by row): TextureTransformTest's arrows
// point at their green markers with this sense; texCoord overrides the reference's.
void GltfMaterials::readTransform(const tinygltf::Value& transform, const std::string& element, TextureView& view) {
    const auto vec2Or = [&](const char* key, glm::dvec2 fallback) {
        if (!transform.IsObject() || !transform.Has(key)) return fallback;
        const tinygltf::Value& value = transform.Get(key);
        if (!value.IsArray() || value.ArrayLen() != 2 || !value.Get(0).IsNumber() || !value.Get(1).IsNumber())
            fail(fmt::format("{}.{}", element, key), "needs 2 numbers");
        return glm::dvec2(value.Get(0).GetNumberAsDouble(), value.Get(1).GetNumberAsDouble());
    };
    const glm::dvec2 offset = vec2Or("offset", glm::dvec2(0.0));
    const glm::dvec2 scale = vec2Or("scale", glm::dvec2(1.0));
    const double rotation = numberOr(transform, "rotation", 0.0, element);
    if (transform.IsObject() && transform.Has("texCoord")) {
        const tinygltf::Value& value = transform.Get("texCoord");
        if (!value.IsInt()) fail(element + ".texCoord", "not an integer");
        view.texCoord = value.Get<int>();
    }
    for (const double v : {offset.x, offset.y, scale.x, scale.y, rotation})
        if (!std::isfinite(v) || std::abs(v) > 1.0e6) fail(element, "offset, rotation and scale must be finite (within 1e6)");
    const double c = std::cos(rotation), s = std::sin(rotation);
    view.uvRow0 = glm::vec3(float(c * scale.x), float(s * scale.y), float(offset.x));
    view.uvRow1 = glm::vec3(float(-s * scale.x), float(c * scale.y), float(offset.y));
}

// Decoded image (1-4 channels, 8 or 16 bits) -> RGBA8, R in the low byte. Grey expands to RGB.
Texture GltfMaterials::convertImage(int source, bool srgb) {
    const tinygltf::Image& image = m_model.images[source];
    const std::string element = fmt::format("images[{}]", source);
    if (image.width <= 0 || image.height <= 0 || image.image.empty()) fail(element, "the image was not decoded");
    if (image.component < 1 || image.component > 4 || (image.bits != 8 && image.bits != 16))
        fail(element, fmt::format("unsupported pixel format ({} channels of {} bits)", image.component, image.bits));
    const size_t pixels = size_t(image.width) * size_t(image.height);
    const bool sixteenBit = image.bits == 16;
    const size_t channels = static_cast<size_t>(image.component);
    if (image.image.size() < pixels * channels * (sixteenBit ? 2 : 1)) fail(element, "decoded image data is truncated");
    Texture t;
    t.name = image.name.empty() ? element : image.name;
    t.width = static_cast<uint32_t>(image.width);
    t.height = static_cast<uint32_t>(image.height);
    t.srgb = srgb;
    t.rgba8.resize(pixels);
    for (size_t p = 0; p < pixels; ++p) {
        uint8_t c[4] = {0, 0, 0, 255};
        for (size_t k = 0; k < channels; ++k) c[k] = channel(image.image, p * channels + k, sixteenBit);
        if (channels <= 2) {  // grey, or grey + alpha
            c[3] = channels == 2 ? c[1] : uint8_t(255);
            c[1] = c[2] = c[0];
        }
        t.rgba8[p] = uint32_t(c[0]) | (uint32_t(c[1]) << 8) | (uint32_t(c[2]) << 16) | (uint32_t(c[3]) << 24);
    }
    return t;
}

}  // namespace vkp
