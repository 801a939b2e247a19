// GPU data layouts shared by the host (C++/GLM) and the shaders (std430). Each struct is followed
// by its size, asserted on the host. vec3 members always start at a multiple of 16 bytes so the
// C++ (4-byte aligned vec3) and std430 (16-byte aligned vec3) layouts agree.
#ifndef VKP_GPU_TYPES_GLSL
#define VKP_GPU_TYPES_GLSL
#include "compat.glsl"
SHARED_BEGIN

// Triangle positions in world space; traversal reads only this buffer. v0.w is
// kTriangleAlphaTested when the triangle's material has an alpha test (alphaMode MASK or BLEND),
// kTriangleBackdrop on a sky box's triangle that only camera rays see (host/lights/backdrop.h;
// traced like an alpha-tested one), else 0; v1.w is the index of
// its entry in the light list (as a float), -1 when it is not a light; v2.w is 1 when camera rays
// skip its back face (glTF doubleSided false and not transmissive, docs/scene-format.md "Back
// faces"), else 0.
struct GpuTriangle {
    vec4 v0;
    vec4 v1;
    vec4 v2;
};
STATIC_ASSERT_SIZE(GpuTriangle, 48)
const float kTriangleAlphaTested = 1.0f;  // GpuTriangle v0.w
const float kTriangleBackdrop = 2.0f;

// Shading attributes of the triangle with the same index as in the GpuTriangle buffer. Unit
// vectors are octahedral (shared/photon.glsl encodeOctahedral, 16+16 bits), colours RGBA8, so
// the per-vertex data of glTF (two TEXCOORD sets, COLOR_0, NORMAL, TANGENT) fit 96 bytes.
struct GpuTriangleShading {
    vec4 uv01;              // TEXCOORD_0 of vertex 0 (xy) and 1 (zw)
    vec2 uv2;
    uint material;
    float emitterPdfArea;   // light-selection probability / area for emissive triangles, else 0
    vec4 uvB01;             // TEXCOORD_1 of vertex 0 (xy) and 1 (zw)
    vec2 uvB2;
    uint n0;                // world-space vertex normals, octahedral
    uint n1;
    uint n2;
    uint color0;            // COLOR_0 of each vertex (packUnorm4x8; white when the mesh has none)
    uint color1;
    uint color2;
    uint tangent0;          // world-space vertex tangents, octahedral (with normal maps only)
    uint tangent1;
    uint tangent2;
    uint tangentSign;       // kTangent*: none (no normal mapping), or the handedness w
};
STATIC_ASSERT_SIZE(GpuTriangleShading, 96)

const uint kTangentNone = 0u;
const uint kTangentPositive = 1u;   // bitangent = cross(normal, tangent)
const uint kTangentNegative = 2u;   // bitangent = -cross(normal, tangent)

// Flattened BVH node: children are adjacent (leftOrFirst, leftOrFirst + 1) for inner nodes;
// leaves (count > 0) hold triangles [leftOrFirst, leftOrFirst + count).
struct GpuBvhNode {
    vec3 boundsMin;
    uint leftOrFirst;
    vec3 boundsMax;
    uint count;
};
STATIC_ASSERT_SIZE(GpuBvhNode, 32)

// Two-level BVH (docs/bvh.md): an instance places one mesh's bottom-level tree in the world.
// The matrices are 3x4, stored as their three rows (world = row . (p, 1)); worldToObject is the
// inverse. Hit ids from firstId on belong to this instance (id - firstId = the triangle's index
// within its mesh, BVH order).
struct GpuInstance {
    vec4 objectToWorld[3];
    vec4 worldToObject[3];
    uint blasRoot;          // node index of its mesh's BVH root
    uint firstTriangle;     // its mesh's first triangle in the triangle and shading buffers
    uint firstId;           // hit id of that triangle
    uint flags;             // kInstance* bits
};
STATIC_ASSERT_SIZE(GpuInstance, 112)

const uint kInstanceMirrored = 1u;  // the transform's determinant is negative (winding reversed)

// Start of the instance buffer. Hit ids below staticTriangles are indices into the triangle
// buffers (the static, world-space tree at node 0); the others belong to an instance.
struct GpuInstanceHeader {
    uint instanceCount;
    uint tlasRoot;          // node index of the top-level root (when instanceCount > 0)
    uint staticTriangles;
    // The scene's reach (largest |coordinate| of its bounds): the floor of the ray offsets
    // (scene_access.glsl rayEpsilon), so they scale with the scene.
    float rayOffsetScale;
};
STATIC_ASSERT_SIZE(GpuInstanceHeader, 16)

// A top-level leaf: count == kBvhInstanceLeaf, leftOrFirst = the instance's index.
const uint kBvhInstanceLeaf = 0x80000000u;

const uint kMaterialDoubleSided = 1u;
const uint kMaterialThinWalled = 2u;  // transmissive without KHR_materials_volume thickness
const uint kMaterialAlphaMask = 4u;   // alphaMode MASK: a cut-out where alpha < alphaCutoff
const uint kMaterialAlphaBlend = 8u;  // alphaMode BLEND: stochastic coverage = alpha
const uint kMaterialNoEnergyCompensation = 16u;  // the spec's single-scattering GGX (docs/materials.md)

struct GpuMaterial {
    vec4 baseColor;         // linear RGBA factor
    vec3 emissive;          // linear RGB radiance factor, emissive_strength applied
    float metallic;
    float roughness;        // perceptual roughness; alpha = roughness^2
    float transmission;
    float ior;
    float thickness;
    vec3 attenuationCoeff;  // Beer-Lambert sigma_a per metre: -ln(attenuationColor)/distance
    uint flags;
    int baseColorTexture;   // index into the texture table, -1 when absent
    int metallicRoughnessTexture;
    int emissiveTexture;
    int transmissionTexture;  // KHR_materials_transmission, R channel; -1 when absent
    int normalTexture;      // tangent-space normal map, -1 when absent
    float normalScale;
    float alphaCutoff;
    float dispersion;       // KHR_materials_dispersion: 20 / Abbe number; zero: one index for all wavelengths
    // KHR_materials_specular / sheen / clearcoat (docs/materials.md); textures -1 when absent.
    vec3 specularColor;     // specularColorFactor (F0 colour of the dielectric)
    float specular;         // specularFactor (dielectric specular weight and F90)
    vec3 sheenColor;        // sheenColorFactor; zero: no sheen
    float sheenRoughness;   // sheenRoughnessFactor
    float clearcoat;        // clearcoatFactor; zero: no coat
    float clearcoatRoughness;
    int specularTexture;          // A channel
    int specularColorTexture;     // RGB, sRGB
    int sheenColorTexture;        // RGB, sRGB
    int sheenRoughnessTexture;    // A channel
    int clearcoatTexture;         // R channel
    int clearcoatRoughnessTexture;  // G channel
    int clearcoatNormalTexture;     // the coat's tangent-space normal map, -1 when absent
    float clearcoatNormalScale;     // its normalTextureInfo.scale
    float anisotropy;               // KHR_materials_anisotropy: anisotropyStrength; zero: isotropic
    int anisotropyTexture;          // RG direction in tangent space, B strength (linear)
    vec2 anisotropyRotation;        // cos and sin of anisotropyRotation
    float iridescence;              // KHR_materials_iridescence: iridescenceFactor; zero: no film
    float iridescenceIor;
    float iridescenceThicknessMin;  // nanometres
    float iridescenceThicknessMax;
    int iridescenceTexture;         // R channel
    int iridescenceThicknessTexture;  // G channel
};
STATIC_ASSERT_SIZE(GpuMaterial, 208)

const uint kLightPoint = 0u;
const uint kLightSpot = 1u;
const uint kLightDirectional = 2u;
const uint kLightTriangle = 3u;
// Light from infinitely far away in every direction (shared/environment.glsl): a constant
// (intensity = radiance, envWidth 0) or an equirectangular map. At most one, the last light.
const uint kLightEnvironment = 5u;  // 4 is the raster pass's kLightAreaSample (shared/shadow_volume.glsl)

// GpuLight.envFlags: sample a map uniformly over the sphere instead of by its distribution (the
// baseline of the importance-sampling benchmark, --env-sampling uniform).
const uint kEnvironmentSampleUniform = 1u;

struct GpuLight {
    vec3 position;          // point/spot position (world)
    uint type;
    vec3 direction;         // spot/directional: direction the light travels (world, unit)
    float spotScale;        // glTF cone falloff: t = saturate(cos * scale + offset), falloff = t*t
    vec3 intensity;         // W/sr (point, spot), W/m^2 (directional), unused for triangles
    float spotOffset;
    uint triangle;          // kLightTriangle: index of the emissive triangle
    float selectPdf;        // probability of choosing this light for next-event estimation
    uint envFlags;          // kLightEnvironment: kEnvironment* bits
    float pad1;
    // kLightEnvironment with a map (shared/environment.glsl EnvironmentMap): its first float in
    // the texel buffer, its size (width 0: the constant `intensity`) and rotation about +Y.
    uint envOffset;
    uint envWidth;
    uint envHeight;
    float envRotation;
};
STATIC_ASSERT_SIZE(GpuLight, 80)

const uint kTextureWrapRepeat = 0u;      // = vkp::TextureWrap
const uint kTextureWrapClamp = 1u;
const uint kTextureWrapMirrored = 2u;
const uint kTextureFilterLinear = 0u;
const uint kTextureFilterNearest = 1u;
const uint kTextureMipmapNone = 0u;     // = MipmapMode (scene.h)
const uint kTextureMipmapNearest = 1u;
const uint kTextureMipmapLinear = 2u;

// Texture views (scene.h TextureView): a rectangle of the texture atlas (the array image of
// shared/kernels/scene.glsl, host/gpu_scene/texture_atlas.h), the TEXCOORD set, the
// KHR_texture_transform and the sampler. Materials index these.
struct GpuTexture {
    uint origin;            // the texture's top-left texel in its atlas layer: x | (y << 16)
    uint width;             // as packed (after any downscaling)
    uint height;
    uint srgb;              // 1: colour data encoded with the sRGB transfer function (read via the sRGB view)
    vec4 uvRow0;            // uv' = (dot(uvRow0.xyz, (u, v, 1)), dot(uvRow1.xyz, (u, v, 1)))
    vec4 uvRow1;
    uint texCoord;          // 0: TEXCOORD_0, 1: TEXCOORD_1
    uint wrapS;             // kTextureWrap*
    uint wrapT;
    uint magFilter;         // kTextureFilter* (magnification)
    uint layer;             // the atlas layer
    uint levels;            // mipmap levels in the atlas rectangle (shared/texture_levels.glsl); 1: none
    uint minFilter;         // kTextureFilter* within a level when minifying (glTF minFilter)
    uint mipmapMode;        // kTextureMipmap*: between levels (glTF minFilter)
};
STATIC_ASSERT_SIZE(GpuTexture, 80)

struct GpuCamera {
    vec3 position;
    float tanHalfFovY;
    vec3 right;             // unit vectors of the camera frame (world)
    float aspect;           // width / height
    vec3 up;
    // Samples per pixel of the render: the camera paths' sampler permutes each dimension's sample
    // numbers within them (owen_sobol.glsl). A sampler setting, kept here because every camera
    // kernel reads this struct and the guided tracer's push constants have no byte left.
    uint pixelSamples;
    vec3 forward;
    // glTF orthographic camera: ymag (half the view's height); 0: pinhole. In the padding, not
    // at the end: the guided path tracer's push constants are exactly the guaranteed 128 bytes.
    float orthoHalfHeight;
};
STATIC_ASSERT_SIZE(GpuCamera, 64)

// Camera ray through a (sub)pixel position (0..width, 0..height, y down): from the pinhole
// through the pixel, or (orthographic) along forward from the pixel's point on the view plane.
INLINE vec3 cameraRayDirection(GpuCamera cam, uint width, uint height, vec2 pixel) {
    if (cam.orthoHalfHeight > 0.0f) return cam.forward;
    vec2 ndc = vec2(2.0f * pixel.x / float(width) - 1.0f, 1.0f - 2.0f * pixel.y / float(height));
    return normalize(cam.forward + ndc.x * cam.aspect * cam.tanHalfFovY * cam.right +
                     ndc.y * cam.tanHalfFovY * cam.up);
}

INLINE vec3 cameraRayOrigin(GpuCamera cam, uint width, uint height, vec2 pixel) {
    if (cam.orthoHalfHeight <= 0.0f) return cam.position;
    vec2 ndc = vec2(2.0f * pixel.x / float(width) - 1.0f, 1.0f - 2.0f * pixel.y / float(height));
    return cam.position + ndc.x * cam.aspect * cam.orthoHalfHeight * cam.right + ndc.y * cam.orthoHalfHeight * cam.up;
}

const uint kPathFlagNoDirectLightSampling = 1u;  // BSDF sampling only (test/reference mode)
// --direct raster (host/passes/raster_direct_pass.h) covers the first vertex's direct light of:
const uint kPathFlagRasterDeltaLights = 2u;  // point, spot and directional lights
const uint kPathFlagRasterAreaLights = 4u;   // emissive triangles (as point samples)

// --direct raster: the raster pass's term is added to every camera sample.
INLINE bool rasterDirectLightOn(uint flags) {
    return (flags & (kPathFlagRasterDeltaLights | kPathFlagRasterAreaLights)) != 0u;
}

// --direct raster at camera-path vertex `depth` (0: the first surface the camera sees): the light
// types (bits 1 << kLight*) whose direct light the raster pass adds there, which next-event
// estimation must skip (directLight's skipTypes) so they are not counted twice.
INLINE uint rasterCoveredLightTypes(uint flags, uint depth) {
    uint skip = 0u;
    if (depth == 0u && (flags & kPathFlagRasterDeltaLights) != 0u)
        skip |= (1u << kLightPoint) | (1u << kLightSpot) | (1u << kLightDirectional);
    if (depth == 0u && (flags & kPathFlagRasterAreaLights) != 0u) skip |= 1u << kLightTriangle;
    return skip;
}

// --direct raster: emission of an area light found at vertex `depth` by a BSDF sample (not a
// delta lobe) from the first vertex. The raster term holds all of a covered area light's light
// at the first vertex, so this emission is dropped instead of MIS-weighted against the skipped
// next-event estimate. Emission behind delta bounces is not covered and counts.
INLINE bool rasterCoversEmission(uint flags, uint depth, bool lastDelta) {
    return depth == 1u && !lastDelta && (flags & kPathFlagRasterAreaLights) != 0u;
}

// Camera rays through pixel centres, no jitter: the raster term is evaluated there (tests).
const uint kPathFlagPixelCentres = 8u;
// Guided path tracer: Russian roulette by the guide's estimate of what the path still brings
// (--guide-rr on, shared/guiding.glsl guideSurvival).
const uint kPathFlagGuideRoulette = 16u;

// Push constants of pathtrace.comp.
struct PathTraceParams {
    GpuCamera camera;
    uint width;
    uint height;
    uint firstSample;       // sample index of the first sample this dispatch adds per pixel
    uint sampleCount;       // samples per pixel this dispatch adds
    uint seed;
    uint maxDepth;          // path vertices after the camera; Russian roulette ends most earlier
    uint lightCount;
    uint flags;
};
STATIC_ASSERT_SIZE(PathTraceParams, 96)

SHARED_END
#endif
