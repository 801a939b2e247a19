#include "scene/gltf_extensions.h"

#include <array>

namespace vkp {
namespace {

using enum ExtensionSupport;

constexpr std::array kExtensions{
    GltfExtension{"KHR_lights_punctual", Read, "point, spot and directional lights (range is ignored)"},
    GltfExtension{"KHR_materials_emissive_strength", Read, "multiplies the emission"},
    GltfExtension{"KHR_materials_ior", Read, "index of refraction"},
    GltfExtension{"KHR_materials_specular", Read, "specular strength and F0 colour, factors and textures"},
    GltfExtension{"KHR_materials_clearcoat", Read, "coat factor, roughness and normal, with their textures"},
    GltfExtension{"KHR_materials_sheen", Read, "Charlie sheen colour and roughness with textures"},
    GltfExtension{"KHR_materials_transmission", Read, "transmissionFactor and transmissionTexture (R)"},
    GltfExtension{"KHR_materials_volume", Read, "thicknessFactor and attenuation (not the thickness texture)"},
    GltfExtension{"KHR_mesh_quantization", Read, "any component type for positions, normals, texture coordinates"},
    GltfExtension{"EXT_mesh_gpu_instancing", Read, "TRANSLATION, ROTATION and SCALE of each instance (other attributes ignored)"},
    GltfExtension{"KHR_draco_mesh_compression", Read, "decoded with libdraco (attributes as float, indices)"},
    GltfExtension{"EXT_meshopt_compression", Read, "decoded with libmeshoptimizer 0.18, all modes and filters"},
    GltfExtension{"KHR_meshopt_compression", Read, "as EXT_meshopt_compression (streams 0.18 decodes; others are errors)"},
    GltfExtension{"KHR_texture_transform", Read, "offset, rotation, scale and texCoord of every material texture"},
    GltfExtension{"KHR_materials_pbrSpecularGlossiness", Read,
                  "diffuse, specular, glossiness and their textures, by the Khronos conversion to metallic-roughness"},
    GltfExtension{"KHR_materials_unlit", Read, "emits its base colour (factor and texture) and reflects nothing"},
    GltfExtension{"KHR_materials_variants", Read, "the variant render --variant names (info lists them); else each primitive's own material"},
    GltfExtension{"KHR_materials_anisotropy", Read,
                  "strength, rotation and texture: anisotropic GGX of the opaque layer's specular lobe"},
    GltfExtension{"KHR_materials_iridescence", Read,
                  "thin-film Fresnel (factor, ior, thickness range, both textures) of the opaque layer and of glass, smooth or rough"},
    GltfExtension{"KHR_materials_dispersion", Read,
                  "index by wavelength from the Abbe number: transmitting paths take one wavelength each"},
    GltfExtension{"EXT_texture_webp", Read, "WebP images (lossy or lossless, alpha too) decoded by libwebp, preferred to the fallback source"},
    GltfExtension{"KHR_materials_diffuse_transmission", Ignored, "opaque diffuse instead"},
    GltfExtension{"KHR_animation_pointer", Ignored, "animations are not played"},
    GltfExtension{"KHR_texture_basisu", Ignored, "KTX2 images are not decoded"},
    GltfExtension{"EXT_texture_avif", Ignored, "AVIF images are not decoded"},
    GltfExtension{"EXT_lights_image_based", Ignored, "no environment light"},
    GltfExtension{"KHR_xmp_json_ld", Ignored, "metadata only"},
};

}  // namespace

std::span<const GltfExtension> knownGltfExtensions() { return kExtensions; }

const GltfExtension* findGltfExtension(std::string_view name) {
    for (const GltfExtension& e : kExtensions)
        if (e.name == name) return &e;
    return nullptr;
}

bool gltfExtensionIsRead(std::string_view name) {
    const GltfExtension* e = findGltfExtension(name);
    return e && e->support == Read;
}

std::string_view extensionSupportName(ExtensionSupport support) { return support == Read ? "read" : "ignored"; }

}  // namespace vkp
