// The renderer's view of a scene: flattened world-space triangles, materials, textures, punctual
// lights and cameras. Produced by the glTF loader; consumed by the BVH builder and the passes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/environment.h"

namespace vkp {

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};
    void grow(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void grow(const Bounds& b) { min = glm::min(min, b.min); max = glm::max(max, b.max); }
    bool empty() const { return min.x > max.x; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return max - min; }
};

struct Texture {
    std::string name;               // glTF image name or "images[i]"
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint32_t> rgba8;    // row-major, top row first, R in the low byte
    bool srgb = false;              // base colour and emissive textures are sRGB-encoded
};

// How a material's texture reference samples its image: glTF's texture info (texCoord set),
// sampler (wrap modes, filters, mipmaps) and KHR_texture_transform. Materials index these
// views (Scene::textureViews); several views may share one image.
enum class TextureWrap : uint32_t { Repeat = 0, ClampToEdge = 1, MirroredRepeat = 2 };  // = kTextureWrap* in GLSL
// glTF minFilter's choice between mipmap levels (docs/scene-format.md "Samplers"): none (level 0
// only: NEAREST, LINEAR), the nearest level (*_MIPMAP_NEAREST) or a blend of the two nearest
// (*_MIPMAP_LINEAR, also what vkphoton does when a sampler leaves minFilter out).
enum class MipmapMode : uint32_t { None = 0, Nearest = 1, Linear = 2 };  // = kTextureMipmap* in GLSL

struct TextureView {
    int image = -1;                  // index into Scene::textures
    int texCoord = 0;                // TEXCOORD_n set (0 or 1 on the device)
    glm::vec3 uvRow0{1.0f, 0.0f, 0.0f};  // KHR_texture_transform as two rows: uv' = (row0, row1) . (u, v, 1)
    glm::vec3 uvRow1{0.0f, 1.0f, 0.0f};
    TextureWrap wrapS = TextureWrap::Repeat;
    TextureWrap wrapT = TextureWrap::Repeat;
    bool nearest = false;            // magFilter NEAREST (9728); otherwise bilinear
    bool minNearest = false;         // minFilter NEAREST or NEAREST_MIPMAP_*: the nearest texel of a level
    MipmapMode mipmaps = MipmapMode::Linear;  // minFilter's mipmap mode
    bool operator<(const TextureView& o) const;  // for de-duplication
};

enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

// glTF metallic-roughness material with the extensions vkphoton supports.
struct Material {
    std::string name;
    glm::vec4 baseColor{1.0f};
    glm::vec3 emissive{0.0f};       // emissiveFactor * KHR_materials_emissive_strength
    float metallic = 1.0f;
    float roughness = 1.0f;
    float transmission = 0.0f;      // KHR_materials_transmission: transmissionFactor
    int transmissionTexture = -1;   // its R channel multiplies transmissionFactor
    float ior = 1.5f;               // KHR_materials_ior
    float thickness = 0.0f;         // KHR_materials_volume; 0 (or no extension) = thin-walled
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = std::numeric_limits<float>::infinity();
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    float normalScale = 1.0f;       // normalTexture.scale
    int normalTexture = -1;
    int baseColorTexture = -1;      // indices into Scene::textureViews
    int metallicRoughnessTexture = -1;
    int emissiveTexture = -1;
    float specular = 1.0f;          // KHR_materials_specular: specularFactor (0: pure Lambert)
    glm::vec3 specularColor{1.0f};  // specularColorFactor
    int specularTexture = -1;       // A channel
    int specularColorTexture = -1;  // RGB, sRGB
    glm::vec3 sheenColor{0.0f};     // KHR_materials_sheen: sheenColorFactor (0: no sheen)
    float sheenRoughness = 0.0f;
    int sheenColorTexture = -1;     // RGB, sRGB
    int sheenRoughnessTexture = -1; // A channel
    float clearcoat = 0.0f;         // KHR_materials_clearcoat: clearcoatFactor (0: no coat)
    float clearcoatRoughness = 0.0f;
    int clearcoatTexture = -1;      // R channel
    int clearcoatRoughnessTexture = -1;  // G channel
    int clearcoatNormalTexture = -1;     // tangent-space normal of the coat (RGB), as normalTexture
    float clearcoatNormalScale = 1.0f;   // clearcoatNormalTexture.scale
    float anisotropy = 0.0f;             // KHR_materials_anisotropy: anisotropyStrength (0: isotropic)
    float anisotropyRotation = 0.0f;     // radians, counter-clockwise from the tangent
    int anisotropyTexture = -1;          // RG: direction in tangent space, B: strength (linear)
    float iridescence = 0.0f;            // KHR_materials_iridescence: iridescenceFactor (0: no film)
    float iridescenceIor = 1.3f;
    float iridescenceThicknessMin = 100.0f;  // nanometres
    float iridescenceThicknessMax = 400.0f;
    int iridescenceTexture = -1;             // R channel multiplies the factor
    int iridescenceThicknessTexture = -1;    // G channel: from minimum (0) to maximum (1)
    float dispersion = 0.0f;                 // KHR_materials_dispersion: 20 / Abbe number (0: none)
    std::vector<std::string> extensions;  // the glTF extensions the material and its textures name
};

struct Triangle {
    glm::vec3 p[3];                 // world-space positions
    glm::vec3 n[3];                 // world-space unit normals (computed when the mesh has none)
    glm::vec2 uv[3]{};              // TEXCOORD_0, zero when absent
    uint32_t material = 0;          // index into Scene::materials
    glm::vec2 uv1[3]{};             // TEXCOORD_1, zero when absent
    glm::vec4 color[3]{glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f)};  // COLOR_0 (RGBA), 1 when absent
    glm::vec4 tangent[3]{};         // world-space unit tangent (xyz) and handedness (w = +-1); w = 0: none
};

enum class LightType { Point, Spot, Directional };

// KHR_lights_punctual light, converted to radiometric units (see docs/scene-format.md):
// point/spot intensity [cd] / 683 lm/W -> W/sr; directional illuminance [lux] / 683 -> W/m^2.
struct PunctualLight {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // direction the light travels (world, unit)
    glm::vec3 intensity{0.0f};               // radiometric, colour included
    float innerConeAngle = 0.0f;             // radians (spot only)
    float outerConeAngle = 0.7853981634f;
};

struct Camera {
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};    // unit
    glm::vec3 up{0.0f, 1.0f, 0.0f};          // unit, orthogonal to forward
    float yfov = 0.6911f;                    // radians
    float aspectRatio = 0.0f;                // 0: take it from the image size
    float orthoHalfHeight = 0.0f;            // orthographic: glTF ymag (the width follows the image); 0: perspective
};

// What the glTF file holds beside the rendered scene, for `vkphoton info` (filled by the loader).
struct AnimationInfo {
    std::string name;
    size_t channels = 0;
    size_t samplers = 0;
};

struct SceneFileInfo {
    std::vector<std::string> extensionsUsed;      // as the file lists them
    std::vector<std::string> extensionsRequired;
    size_t nodes = 0;                             // in the whole file, not only the scene's tree
    size_t skins = 0;
    std::vector<AnimationInfo> animations;        // not played: the scene is its rest pose
    std::vector<std::string> materialVariants;    // KHR_materials_variants' names, in the file's order
};

// A mesh placed by instances (docs/bvh.md): its triangles in object space (Triangle's fields
// then hold object-space positions, normals and tangents), one bottom-level BVH for all its
// instances. The loader makes meshes of those glTF meshes that are drawn several times
// (EXT_mesh_gpu_instancing or several nodes) or animated; everything else is flattened into
// Scene::triangles. Meshes never emit light (emissive ones stay flattened).
struct Mesh {
    std::string name;
    std::vector<Triangle> triangles;
    Bounds bounds;                  // object space
};

// One placement of a mesh: object-to-world transform (affine, invertible).
struct Instance {
    uint32_t mesh = 0;              // index into Scene::meshes
    glm::mat4 transform{1.0f};
    int node = -1;                  // the glTF node that placed it (-1: none)
};

// A glTF node's mesh flattened into Scene::triangles: triangles [first, first + count), in the
// loader's walk order (one per node, or per EXT_mesh_gpu_instancing transform).
struct Drawing {
    int node = -1;                  // the glTF node that draws it
    int mesh = -1;                  // its glTF mesh
    uint32_t first = 0;
    uint32_t count = 0;
};

struct Scene {
    std::filesystem::path source;
    std::vector<Triangle> triangles;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<TextureView> textureViews;   // what materials' texture indices refer to
    std::vector<PunctualLight> lights;
    std::vector<Camera> cameras;             // perspective and orthographic cameras in node order
    Bounds bounds;
    size_t droppedDegenerateTriangles = 0;
    SceneFileInfo file;
    size_t droppedDuplicateTriangles = 0;    // the same three world positions as an earlier one
    Environment environment;                 // --env (scene/environment.h), not from the file
    bool energyCompensation = true;          // multiple-scattering GGX (render --no-energy-compensation)
    std::vector<Mesh> meshes;                // instanced meshes (object space), docs/bvh.md
    std::vector<Instance> instances;         // their placements; Scene::triangles holds the rest
    std::vector<Drawing> drawings;           // where each flattened node's triangles are
    // Nodes whose drawings are sky boxes around an environment-lit scene (lights/backdrop.h):
    // camera rays see them, no other ray does, so the environment lights the scene through them.
    std::vector<int> backdropNodes;          // glTF node indices, ascending
};

// Every triangle in world space: Scene::triangles, then each instance's mesh transformed (the
// single-level scene the instances stand for; tests and the raster pass compare against it).
std::vector<Triangle> flattenedTriangles(const Scene& scene);
// One instance's triangles in world space (normals by the inverse transpose; a mirroring
// transform swaps two vertices and flips tangent handedness, as the loader does).
void appendInstanceTriangles(const Mesh& mesh, const glm::mat4& transform, std::vector<Triangle>& out);

}  // namespace vkp
