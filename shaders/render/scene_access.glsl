// GLSL-only scene access shared by the integrator shaders: buffer declarations, surface
// interaction at a hit, texture lookups and next-event light sampling. Bindings are the ones
// named in shared/kernels/scene.glsl.
#ifndef VKP_SCENE_ACCESS_GLSL
#define VKP_SCENE_ACCESS_GLSL

#include "shared/gpu_types.glsl"
#include "shared/kernels/scene.glsl"
#include "shared/constants.glsl"
#include "shared/sampling.glsl"
#define VKP_BSDF_TABLES_BINDING kSceneTablesBinding  // the BSDF's albedo tables (shared/bsdf_tables.glsl)
#include "shared/bsdf.glsl"
#include "common/termination_counters.glsl"

layout(std430, set = 0, binding = kSceneTrianglesBinding) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, set = 0, binding = kSceneBvhNodesBinding) readonly buffer BvhNodes { GpuBvhNode bvhNodes[]; };
layout(std430, set = 0, binding = kSceneShadingBinding) readonly buffer Shading { GpuTriangleShading shading[]; };
layout(std430, set = 0, binding = kSceneMaterialsBinding) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = kSceneLightsBinding) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = kSceneLightCdfBinding) readonly buffer LightCdf { float lightCdf[]; };
layout(std430, set = 0, binding = kSceneTexturesBinding) readonly buffer Textures { GpuTexture textures[]; };
// binding kSceneTablesBinding: declared by shared/bsdf_tables.glsl (float bsdfTablesData[]).
layout(std430, set = 0, binding = kSceneTexelsBinding) readonly buffer EnvironmentFloats { float environmentFloats[]; };
layout(std430, set = 0, binding = kSceneInstancesBinding) readonly buffer Instances {
    GpuInstanceHeader instanceHeader;
    GpuInstance instances[];
};
layout(set = kSceneTextureSet, binding = kSceneTextureUnormBinding) uniform sampler2DArray sceneTexturesUnorm;
layout(set = kSceneTextureSet, binding = kSceneTextureSrgbBinding) uniform sampler2DArray sceneTexturesSrgb;

// Whether the scene has any texture (specialization constant, vk::SceneSpecialization): without,
// no material names one, and the texture lookup, which lavapipe would run (masked) at every
// call site for the whole SIMD group, is compiled out (docs/bvh.md).
layout(constant_id = kSceneHasTexturesId) const bool kSceneHasTextures = true;

#include "shared/hash.glsl"
#include "shared/photon.glsl"
#include "shared/light_selection.glsl"
#include "shared/spherical_triangle.glsl"
#include "shared/texture_levels.glsl"

// Texel (x, y) of a texture's mipmap level whose first texel is `level` texels from the
// rectangle's (shared/texture_levels.glsl); sRGB textures through the sRGB view, which decodes
// to linear.
vec4 texelValue(GpuTexture tex, uvec2 level, uint x, uint y) {
    ivec3 p = ivec3(int((tex.origin & 0xffffu) + level.x + x), int((tex.origin >> 16u) + level.y + y), int(tex.layer));
    return tex.srgb != 0u ? texelFetch(sceneTexturesSrgb, p, 0) : texelFetch(sceneTexturesUnorm, p, 0);
}

// Texel index i (any integer) on an axis of n texels under a glTF wrap mode.
uint wrapTexel(int i, int n, uint mode) {
    if (mode == kTextureWrapClamp) return uint(clamp(i, 0, n - 1));
    if (mode == kTextureWrapMirrored) {
        int period = 2 * n;
        int m = ((i % period) + period) % period;
        return uint(m < n ? m : period - 1 - m);
    }
    return uint(((i % n) + n) % n);
}

// One mipmap level of a texture at st (uv after the view's transform): the nearest texel or
// bilinear, with the view's wrap modes.
vec4 sampleLevel(GpuTexture tex, vec2 st, uint level, uint texelFilter) {
    int w = int(mipLevelSize(tex.width, level));
    int h = int(mipLevelSize(tex.height, level));
    uvec2 origin = uvec2(mipLevelColumn(tex.width, level), mipLevelRow(tex.height, level));
    vec2 texel = st * vec2(float(w), float(h));
    if (texelFilter == kTextureFilterNearest) {
        vec2 base = floor(texel);
        return texelValue(tex, origin, wrapTexel(int(base.x), w, tex.wrapS), wrapTexel(int(base.y), h, tex.wrapT));
    }
    texel -= 0.5f;
    vec2 base = floor(texel);
    vec2 f = texel - base;
    uint x0 = wrapTexel(int(base.x), w, tex.wrapS);
    uint x1 = wrapTexel(int(base.x) + 1, w, tex.wrapS);
    uint y0 = wrapTexel(int(base.y), h, tex.wrapT);
    uint y1 = wrapTexel(int(base.y) + 1, h, tex.wrapT);
    vec4 a = mix(texelValue(tex, origin, x0, y0), texelValue(tex, origin, x1, y0), f.x);
    vec4 b = mix(texelValue(tex, origin, x0, y1), texelValue(tex, origin, x1, y1), f.x);
    return mix(a, b, f.y);
}

// The one texture lookup of every material texture: `index` names a texture view (image, TEXCOORD
// set, KHR_texture_transform, sampler); uv holds TEXCOORD_0 (xy) and TEXCOORD_1 (zw).
// `footprint` (SurfaceHit.textureFootprint; 0: none) is, per TEXCOORD set, the uv area the ray's
// cone covers at the hit, as a square's side squared. Times the view's uv scale and the image's
// texels it is the texels one sample covers; its log2 / 2 is the level of detail (ray cones:
// Akenine-Moeller et al. 2019, "Texture Level of Detail Strategies for Real-Time Ray Tracing").
// Up to level 0 the sampler's magFilter applies; beyond, its minFilter: within a level (nearest
// or bilinear) and between levels (level 0 only, the nearest level, or a blend of two).
vec4 sampleTexture(int index, vec4 uv, vec2 footprint) {
    if (!kSceneHasTextures) return vec4(1.0f);  // never called then: compiles the lookup out
    GpuTexture tex = textures[index];
    vec2 set = tex.texCoord == 1u ? uv.zw : uv.xy;
    vec2 st = vec2(dot(tex.uvRow0.xyz, vec3(set, 1.0f)), dot(tex.uvRow1.xyz, vec3(set, 1.0f)));
    // Far-away coordinates lose all precision; keep them finite and the integer casts defined.
    st = clamp(st, vec2(-1.0e6f), vec2(1.0e6f));
    float uvScale = abs(tex.uvRow0.x * tex.uvRow1.y - tex.uvRow0.y * tex.uvRow1.x);
    float texels = (tex.texCoord == 1u ? footprint.y : footprint.x) * uvScale * float(tex.width) * float(tex.height);
    float lod = texels > 0.0f && texels < kInfinity ? 0.5f * log2(texels) : 0.0f;
    bool minified = lod > 0.0f;
    uint texelFilter = minified ? tex.minFilter : tex.magFilter;
    float level = minified && tex.mipmapMode != kTextureMipmapNone ? min(lod, float(tex.levels - 1u)) : 0.0f;
    if (tex.mipmapMode == kTextureMipmapNearest) level = min(floor(level + 0.5f), float(tex.levels - 1u));
    // One or two levels through one inlined sampleLevel (a loop, not two calls: lavapipe runs
    // both sides of a branch, but leaves a loop when no lane of the group goes on).
    uint first = uint(level);
    float blend = level - float(first);
    vec4 value = vec4(0.0f);
    for (uint k = 0u; k < 2u; ++k) {
        value += (k == 0u ? 1.0f - blend : blend) * sampleLevel(tex, st, first + k, texelFilter);
        if (!(blend > 0.0f)) break;
    }
    return value;
}

// The uv area (per TEXCOORD set) a ray cone of width `coneWidth` covers where it meets the
// triangle (world-space corners v0, v1, v2, uv in s) at an angle whose cosine to the normal is
// `cosine`, as a square's side squared: the cone's ellipse on the surface, coneWidth^2 / cosine
// in area, times the triangle's uv area over its world area (sampleTexture's footprint). The
// ellipse's area, not its long axis squared (coneWidth^2 / cosine^2, Akenine-Moeller et al.'s
// isotropic choice), sets the level: at grazing angles the long axis blurs the texture across the
// short one, and on a textured floor to the horizon the area's level gave 2.6-4.5x less error
// than no mipmaps at 1-64 spp where the long axis's gave 1.7x at 1 spp and more error from 16 spp
// on (docs/benchmarks.md "Texture level of detail"). Zero without a cone.
vec2 textureFootprint(GpuTriangleShading s, vec3 v0, vec3 v1, vec3 v2, float cosine, float coneWidth) {
    float worldArea = length(cross(v1 - v0, v2 - v0));  // both areas doubled: the ratio is the same
    vec2 a = s.uv01.zw - s.uv01.xy;
    vec2 b = s.uv2 - s.uv01.xy;
    vec2 c = s.uvB01.zw - s.uvB01.xy;
    vec2 d = s.uvB2 - s.uvB01.xy;
    vec2 uvArea = vec2(abs(a.x * b.y - a.y * b.x), abs(c.x * d.y - c.y * d.x));
    float surface = coneWidth * coneWidth / (max(cosine, 1.0e-4f) * max(worldArea, 1.0e-30f));
    return coneWidth > 0.0f ? uvArea * surface : vec2(0.0f);
}

// The texels a surface point reads from its material's textures (sampleMaterialTextures), vec4(1)
// for a texture the material lacks or that the point does not need (a factor times 1 is itself).
struct MaterialTexels {
    vec4 baseColor;
    vec4 metallicRoughness;
    vec4 emissive;
    vec4 normal;
    vec4 specular;
    vec4 specularColor;
    vec4 sheenColor;
    vec4 sheenRoughness;
    vec4 clearcoat;
    vec4 clearcoatRoughness;
    vec4 transmission;
    vec4 clearcoatNormal;
    vec4 anisotropy;
    vec4 iridescence;
    vec4 iridescenceThickness;
};

// Texture slots of a material (bits of sampleMaterialTextures' `slots`).
const uint kMaterialTextureBaseColor = 0u;
const uint kMaterialTextureMetallicRoughness = 1u;
const uint kMaterialTextureEmissive = 2u;
const uint kMaterialTextureNormal = 3u;
const uint kMaterialTextureSpecular = 4u;
const uint kMaterialTextureSpecularColor = 5u;
const uint kMaterialTextureSheenColor = 6u;
const uint kMaterialTextureSheenRoughness = 7u;
const uint kMaterialTextureClearcoat = 8u;
const uint kMaterialTextureClearcoatRoughness = 9u;
const uint kMaterialTextureTransmission = 10u;
const uint kMaterialTextureClearcoatNormal = 11u;
const uint kMaterialTextureAnisotropy = 12u;
const uint kMaterialTextureIridescence = 13u;
const uint kMaterialTextureIridescenceThickness = 14u;
const uint kMaterialTextureSlots = 15u;

int materialTexture(GpuMaterial m, uint slot) {
    switch (slot) {
    case kMaterialTextureBaseColor: return m.baseColorTexture;
    case kMaterialTextureMetallicRoughness: return m.metallicRoughnessTexture;
    case kMaterialTextureEmissive: return m.emissiveTexture;
    case kMaterialTextureNormal: return m.normalTexture;
    case kMaterialTextureSpecular: return m.specularTexture;
    case kMaterialTextureSpecularColor: return m.specularColorTexture;
    case kMaterialTextureSheenColor: return m.sheenColorTexture;
    case kMaterialTextureSheenRoughness: return m.sheenRoughnessTexture;
    case kMaterialTextureClearcoat: return m.clearcoatTexture;
    case kMaterialTextureClearcoatRoughness: return m.clearcoatRoughnessTexture;
    case kMaterialTextureClearcoatNormal: return m.clearcoatNormalTexture;
    case kMaterialTextureAnisotropy: return m.anisotropyTexture;
    case kMaterialTextureIridescence: return m.iridescenceTexture;
    case kMaterialTextureIridescenceThickness: return m.iridescenceThicknessTexture;
    default: return m.transmissionTexture;
    }
}

// The slots of the textures m has, among `wanted`; the sheen colour, clearcoat (and its normal), transmission and
// emissive textures only where their factor is non-zero (the texel could not change the result).
uint materialTextureSlots(GpuMaterial m, uint wanted) {
    uint slots = 0u;
    for (uint slot = 0u; slot < kMaterialTextureSlots; ++slot)
        if (materialTexture(m, slot) >= 0) slots |= 1u << slot;
    if (!(maxComponent(m.sheenColor) > 0.0f)) slots &= ~(1u << kMaterialTextureSheenColor);
    if (!(m.clearcoat > 0.0f)) slots &= ~((1u << kMaterialTextureClearcoat) | (1u << kMaterialTextureClearcoatNormal));
    if (!(m.transmission > 0.0f)) slots &= ~(1u << kMaterialTextureTransmission);
    if (!(m.anisotropy > 0.0f)) slots &= ~(1u << kMaterialTextureAnisotropy);
    if (!(m.iridescence > 0.0f))
        slots &= ~((1u << kMaterialTextureIridescence) | (1u << kMaterialTextureIridescenceThickness));
    if (!(m.emissive.r > 0.0f || m.emissive.g > 0.0f || m.emissive.b > 0.0f)) slots &= ~(1u << kMaterialTextureEmissive);
    return slots & wanted;
}

// Samples the textures of m named by `slots` at uv (both TEXCOORD sets), all through ONE
// sampleTexture call site: lavapipe inlines a function at every call, and one call per texture
// slot made the path tracer's shader several times larger, slower to compile and slower to run
// even on untextured scenes. Untextured materials run no iteration.
MaterialTexels sampleMaterialTextures(GpuMaterial m, vec4 uv, vec2 footprint, uint slots) {
    MaterialTexels t;
    t.baseColor = vec4(1.0f);
    t.metallicRoughness = vec4(1.0f);
    t.emissive = vec4(1.0f);
    t.normal = vec4(1.0f);
    t.specular = vec4(1.0f);
    t.specularColor = vec4(1.0f);
    t.sheenColor = vec4(1.0f);
    t.sheenRoughness = vec4(1.0f);
    t.clearcoat = vec4(1.0f);
    t.clearcoatRoughness = vec4(1.0f);
    t.transmission = vec4(1.0f);
    t.clearcoatNormal = vec4(1.0f);
    t.anisotropy = vec4(1.0f);
    t.iridescence = vec4(1.0f);
    t.iridescenceThickness = vec4(1.0f);
    for (uint k = 0u; k < kMaterialTextureSlots && slots != 0u; ++k) {
        uint slot = uint(findLSB(slots));
        slots &= slots - 1u;
        vec4 v = sampleTexture(materialTexture(m, slot), uv, footprint);
        switch (slot) {
        case kMaterialTextureBaseColor: t.baseColor = v; break;
        case kMaterialTextureMetallicRoughness: t.metallicRoughness = v; break;
        case kMaterialTextureEmissive: t.emissive = v; break;
        case kMaterialTextureNormal: t.normal = v; break;
        case kMaterialTextureSpecular: t.specular = v; break;
        case kMaterialTextureSpecularColor: t.specularColor = v; break;
        case kMaterialTextureSheenColor: t.sheenColor = v; break;
        case kMaterialTextureSheenRoughness: t.sheenRoughness = v; break;
        case kMaterialTextureClearcoat: t.clearcoat = v; break;
        case kMaterialTextureClearcoatRoughness: t.clearcoatRoughness = v; break;
        case kMaterialTextureClearcoatNormal: t.clearcoatNormal = v; break;
        case kMaterialTextureAnisotropy: t.anisotropy = v; break;
        case kMaterialTextureIridescence: t.iridescence = v; break;
        case kMaterialTextureIridescenceThickness: t.iridescenceThickness = v; break;
        default: t.transmission = v; break;
        }
    }
    return t;
}

// Both TEXCOORD sets of triangle s at barycentrics (b1, b2).
vec4 interpolatedUv(GpuTriangleShading s, float b1, float b2) {
    float b0 = 1.0f - b1 - b2;
    return vec4(b0 * s.uv01.xy + b1 * s.uv01.zw + b2 * s.uv2, b0 * s.uvB01.xy + b1 * s.uvB01.zw + b2 * s.uvB2);
}

vec4 vertexColor(GpuTriangleShading s, float b1, float b2) {
    return (1.0f - b1 - b2) * unpackUnorm4x8(s.color0) + b1 * unpackUnorm4x8(s.color1) + b2 * unpackUnorm4x8(s.color2);
}

// glTF alphaMode at a candidate hit (the one alpha test of the shared traversal, so camera,
// shadow, photon, importon and gather rays all see the same cut-outs): MASK passes where
// baseColor alpha (factor x texture x COLOR_0) >= alphaCutoff; BLEND where a hash of the ray and
// the triangle falls below alpha (stochastic transparency: the same ray always decides the same
// way, so the same seed gives the same image). OPAQUE always passes.
bool alphaPasses(uint tri, float b1, float b2, vec3 org, vec3 dir) {
    GpuTriangleShading s = shading[tri];
    GpuMaterial m = materials[s.material];
    if ((m.flags & (kMaterialAlphaMask | kMaterialAlphaBlend)) == 0u) return true;
    float alpha = m.baseColor.a * vertexColor(s, b1, b2).a;
    if (m.baseColorTexture >= 0) alpha *= sampleTexture(m.baseColorTexture, interpolatedUv(s, b1, b2), vec2(0.0f)).a;
    if ((m.flags & kMaterialAlphaMask) != 0u) return alpha >= m.alphaCutoff;
    uint h = hashCombine(pcgHash(tri), floatBitsToUint(org.x));
    h = hashCombine(h, floatBitsToUint(org.y));
    h = hashCombine(h, floatBitsToUint(org.z));
    h = hashCombine(h, floatBitsToUint(dir.x));
    h = hashCombine(h, floatBitsToUint(dir.y));
    h = hashCombine(h, floatBitsToUint(dir.z));
    return uintToUnitFloat(h) < alpha;
}
// Called by traceClosest/traceAny (shared/bvh_traverse.glsl) only for hits on triangles with
// v0.w == kTriangleAlphaTested.
#define BVH_ALPHA_TEST(triangle, tri, b1, b2, org, dir) alphaPasses(tri, b1, b2, org, dir)

#include "render/scene_geometry.glsl"  // the traversal's node and triangle reads (texel buffers)
#include "shared/intersect.glsl"
#include "shared/bvh_traverse.glsl"

// The environment map's floats (binding kSceneTexelsBinding holds only them).
#define ENV_FLOAT(i) environmentFloats[(i)]
#include "shared/environment.glsl"

// Distance by which rays leave a surface at p: 1e-4 of p's magnitude (float spacing grows with
// it), and at least 1e-4 of the scene's reach (instanceHeader.rayOffsetScale: a hit near the
// origin on a triangle whose vertices lie far out carries their rounding). Both scale with the
// scene, so a model in millimetres renders as in metres (docs/scene-format.md "Scale").
float rayEpsilon(vec3 p) {
    return 1.0e-4f * max(instanceHeader.rayOffsetScale, max(abs(p.x), max(abs(p.y), abs(p.z))));
}

// Offsets shadow and continuation rays off the surface along the normal, on dir's side.
vec3 offsetRayOrigin(vec3 p, vec3 n, vec3 dir) {
    return p + (dot(dir, n) >= 0.0f ? n : -n) * rayEpsilon(p);
}

#include "render/material_extensions.glsl"

// Emission from the sampled texels (sampleMaterialTextures with the emissive slot).
vec3 emittedRadianceOf(GpuMaterial m, MaterialTexels texels) {
    return m.emissive * texels.emissive.rgb;
}

vec3 emittedRadiance(GpuMaterial m, vec4 uv) {
    vec3 e = m.emissive;
    if (m.emissiveTexture >= 0 && (e.r > 0.0f || e.g > 0.0f || e.b > 0.0f))
        e *= sampleTexture(m.emissiveTexture, uv, vec2(0.0f)).rgb;
    return e;
}

struct SurfaceHit {
    vec3 position;
    vec3 geometricNormal;   // unit, from the winding (front face side)
    vec3 shadingNormal;     // unit, interpolated (and normal-mapped), flipped to the geometric normal's side
    vec3 coatNormal;        // KHR_materials_clearcoat's own normal, on the same side (hasCoatNormal)
    bool hasCoatNormal;     // the coat's normal is not shadingNormal: it has a clearcoatNormalTexture,
                            // or the base has a normal map the coat does not follow (the extension:
                            // without clearcoatNormalTexture the coat is not normal-mapped)
    vec3 anisotropyDirection;  // KHR_materials_anisotropy's direction (world, unit, across shadingNormal);
                               // zero for isotropic materials
    vec4 uv;                // TEXCOORD_0 (xy) and TEXCOORD_1 (zw)
    vec2 textureFootprint;  // the ray cone's uv area per TEXCOORD set (sampleTexture); 0: level 0
    vec4 color;             // COLOR_0 (1 when the mesh has none)
    uint material;
    float emitterPdfArea;
    bool frontFace;         // the ray arrived on the front (counter-clockwise) side
    uint triangle;          // hit id (docs/bvh.md): the static triangle's index, or an instance's
};

// A normal map's normal (glTF: tangent space +X along the tangent, +Y along
// cross(normal, tangent) * w, scaled in xy by the texture info's `scale`) around unit normal n, with
// the interpolated world-space tangent t (not yet orthogonalised), w < 0 as `negative`, and the
// normal texture's texel `texel`.
vec3 normalMapped(float scale, vec3 t, bool negative, vec3 texel, vec3 n) {
    t -= n * dot(n, t);
    float len = length(t);
    if (!(len > 1.0e-6f)) return n;
    t /= len;
    vec3 b = cross(n, t) * (negative ? -1.0f : 1.0f);
    vec3 c = texel * 2.0f - 1.0f;
    vec3 mapped = t * (c.x * scale) + b * (c.y * scale) + n * c.z;
    float mappedLength = length(mapped);
    return mappedLength > 1.0e-6f ? mapped / mappedLength : n;
}

// The normal maps' texture slots: the base's and the coat's.
const uint kNormalMapSlots = (1u << kMaterialTextureNormal) | (1u << kMaterialTextureClearcoatNormal);
// What the surface's frame reads: the normal maps and the anisotropy direction.
const uint kSurfaceFrameSlots = kNormalMapSlots | (1u << kMaterialTextureAnisotropy);

// KHR_materials_anisotropy's direction, world space across unit normal n: the texture's RG mapped
// to [-1, 1] (else tangent space's +X), rotated counter-clockwise by anisotropyRotation, then out of
// tangent space (X along the vertex tangent t, Y along cross(n, t) times its handedness). Without
// usable tangents (no TANGENT attribute and no TEXCOORD to generate them from) the frame of
// orthonormalBasis(n) stands in.
vec3 anisotropyDirectionAt(GpuMaterial m, MaterialTexels texels, bool hasTangent, vec3 tangent, bool negative, vec3 n) {
    vec2 d = m.anisotropyTexture >= 0 ? texels.anisotropy.xy * 2.0f - 1.0f : vec2(1.0f, 0.0f);
    vec2 r = m.anisotropyRotation;
    d = vec2(r.x * d.x - r.y * d.y, r.y * d.x + r.x * d.y);
    vec3 t = tangent - n * dot(n, tangent);
    float len = length(t);
    vec3 b;
    if (hasTangent && len > 1.0e-6f) {
        t /= len;
        b = cross(n, t) * (negative ? -1.0f : 1.0f);
    } else {
        orthonormalBasis(n, t, b);
    }
    vec3 w = t * d.x + b * d.y;
    float wLength = length(w);
    return wLength > 1.0e-6f ? w / wLength : t;
}

// Hit ids (docs/bvh.md): below instanceHeader.staticTriangles the index of a static (world-space)
// triangle in the triangle buffers; from there on an instance's firstId plus the triangle's index
// within its mesh. Instances are stored in firstId order: the hit's instance is the last one
// whose firstId <= id (binary search, at most 32 steps).
uint instanceOfHit(uint id) {
    uint lo = 0u;
    uint hi = instanceHeader.instanceCount - 1u;
    for (uint k = 0u; k < 32u && lo < hi; ++k) {
        uint mid = hi - (hi - lo) / 2u;
        if (instances[mid].firstId <= id) lo = mid; else hi = mid - 1u;
    }
    return lo;
}

// The light-list index of the triangle a hit id names (GpuTriangle.v1.w), -1 when it is no
// light; instanced triangles never are (the loader keeps emissive meshes static).
float lightIndexOfHit(uint id) {
    return !kSceneHasInstances || id < instanceHeader.staticTriangles ? triangles[id].v1.w : -1.0f;
}

// The surface at barycentrics (b1, b2) of the triangle with hit id `id`, in world space: an
// instanced triangle's vertices, normals and tangents go through its instance's transform (normals
// by the inverse transpose; a mirroring transform reverses the winding, so the geometric normal is
// negated and the tangent handedness flipped, as the loader does for flattened meshes).
// `wanted`: the material texture slots (bits 1 << kMaterialTexture*) to sample there, all in one
// loop (sampleMaterialTextures); the normal map's is used here when wanted. `coneWidth`: the width
// of the ray's cone at the hit (Ray.coneWidth and coneSpread), which picks the textures' mipmap
// levels; 0 reads level 0.
SurfaceHit surfaceTexelsAt(uint id, float b1, float b2, vec3 rayDir, float coneWidth, uint wanted,
                           out MaterialTexels texels) {
    uint tri = id;
    bool instanced = kSceneHasInstances && id >= instanceHeader.staticTriangles;  // compiled out without instances
    GpuInstance inst;
    if (instanced) {
        inst = instances[instanceOfHit(id)];
        tri = inst.firstTriangle + (id - inst.firstId);
    }
    GpuTriangle t = triangles[tri];
    GpuTriangleShading s = shading[tri];
    vec3 v0 = t.v0.xyz;
    vec3 v1 = t.v1.xyz;
    vec3 v2 = t.v2.xyz;
    bool mirrored = instanced && (inst.flags & kInstanceMirrored) != 0u;
    if (instanced) {
        v0 = transformPoint3x4(inst.objectToWorld[0], inst.objectToWorld[1], inst.objectToWorld[2], v0);
        v1 = transformPoint3x4(inst.objectToWorld[0], inst.objectToWorld[1], inst.objectToWorld[2], v1);
        v2 = transformPoint3x4(inst.objectToWorld[0], inst.objectToWorld[1], inst.objectToWorld[2], v2);
    }
    float b0 = 1.0f - b1 - b2;
    SurfaceHit hit;
    hit.position = b0 * v0 + b1 * v1 + b2 * v2;
    hit.geometricNormal = normalize(cross(v1 - v0, v2 - v0)) * (mirrored ? -1.0f : 1.0f);
    hit.uv = interpolatedUv(s, b1, b2);
    hit.textureFootprint = textureFootprint(s, v0, v1, v2, abs(dot(rayDir, hit.geometricNormal)), coneWidth);
    hit.color = vertexColor(s, b1, b2);
    vec3 n = b0 * decodeOctahedral(s.n0) + b1 * decodeOctahedral(s.n1) + b2 * decodeOctahedral(s.n2);
    if (instanced)  // inverse transpose: the columns of worldToObject's 3x3 part
        n = n.x * inst.worldToObject[0].xyz + n.y * inst.worldToObject[1].xyz + n.z * inst.worldToObject[2].xyz;
    float len = length(n);
    n = len > 0.0f ? n / len : hit.geometricNormal;
    GpuMaterial m = materials[s.material];
    if (s.tangentSign == kTangentNone) wanted &= ~kNormalMapSlots;
    uint slots = materialTextureSlots(m, wanted);
    texels = sampleMaterialTextures(m, hit.uv, hit.textureFootprint, slots);
    vec3 coat = n;  // the coat's normal: not the base's normal map (KHR_materials_clearcoat)
    hit.hasCoatNormal = m.clearcoat > 0.0f && (slots & kNormalMapSlots) != 0u;
    bool anisotropic = m.anisotropy > 0.0f;
    bool hasTangent = s.tangentSign != kTangentNone && ((slots & kNormalMapSlots) != 0u || anisotropic);
    vec3 tangent = vec3(0.0f);
    bool negative = false;
    if (hasTangent) {
        tangent = b0 * decodeOctahedral(s.tangent0) + b1 * decodeOctahedral(s.tangent1) +
                  b2 * decodeOctahedral(s.tangent2);
        if (instanced)
            tangent = transformVector3x4(inst.objectToWorld[0], inst.objectToWorld[1], inst.objectToWorld[2], tangent);
        negative = (s.tangentSign == kTangentNegative) != mirrored;
    }
    if ((slots & kNormalMapSlots) != 0u) {
        if ((slots & (1u << kMaterialTextureClearcoatNormal)) != 0u)
            coat = normalMapped(m.clearcoatNormalScale, tangent, negative, texels.clearcoatNormal.xyz, n);
        if ((slots & (1u << kMaterialTextureNormal)) != 0u)
            n = normalMapped(m.normalScale, tangent, negative, texels.normal.xyz, n);
    }
    if (dot(n, hit.geometricNormal) < 0.0f) n = -n;
    if (dot(coat, hit.geometricNormal) < 0.0f) coat = -coat;
    hit.shadingNormal = n;
    hit.coatNormal = hit.hasCoatNormal ? coat : n;
    hit.anisotropyDirection = anisotropic ? anisotropyDirectionAt(m, texels, hasTangent, tangent, negative, n) : vec3(0.0f);
    hit.material = s.material;
    hit.emitterPdfArea = s.emitterPdfArea;
    hit.frontFace = dot(rayDir, hit.geometricNormal) < 0.0f;
    hit.triangle = id;
    return hit;
}

// The surface with its normal maps and anisotropy direction (surfaceTexelsAt without other textures).
SurfaceHit surfaceAt(uint id, float b1, float b2, vec3 rayDir, float coneWidth) {
    MaterialTexels texels;
    return surfaceTexelsAt(id, b1, b2, rayDir, coneWidth, kSurfaceFrameSlots, texels);
}

// The material texture slots the BSDF reads (all but emissive and the normal maps).
const uint kBsdfTextureSlots = ~((1u << kMaterialTextureEmissive) | kNormalMapSlots);

// The material's parameters from the texels at a surface point (sampleMaterialTextures with
// kBsdfTextureSlots at least). COLOR_0 multiplies the base colour (the callers: bsdfParamsAtHit).
BsdfParams bsdfParamsOf(GpuMaterial m, MaterialTexels texels) {
    vec4 base = m.baseColor * texels.baseColor;
    float metallic = m.metallic * texels.metallicRoughness.b;  // glTF: roughness in G, metalness in B
    float roughness = m.roughness * texels.metallicRoughness.g;
    BsdfParams p = makeBsdfParams(base.rgb, clamp(metallic, 0.0f, 1.0f), clamp(roughness, 0.0f, 1.0f));
    p.transmission = clamp(m.transmission * texels.transmission.r, 0.0f, 1.0f);  // KHR_materials_transmission
    p.ior = m.ior;
    p.thinWalled = (m.flags & kMaterialThinWalled) != 0u ? 1u : 0u;
    materialExtensionsAt(m, texels, p);
    return p;
}

// The material's parameters at a surface point (its TEXCOORD sets and texture footprint).
BsdfParams bsdfParamsAtHit(GpuMaterial m, SurfaceHit hit) {
    BsdfParams p = bsdfParamsOf(m, sampleMaterialTextures(m, hit.uv, hit.textureFootprint,
                                                          materialTextureSlots(m, kBsdfTextureSlots)));
    p.baseColor *= hit.color.rgb;
    return p;
}

bool emitsTowards(GpuMaterial m, bool frontFace) {
    return frontFace || (m.flags & kMaterialDoubleSided) != 0u;
}

// Picks a light index with probability lights[i].selectPdf (binary search in the CDF).
uint pickLight(float u, uint lightCount) {
    uint lo = 0u;
    uint hi = lightCount - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (u < lightCdf[mid]) hi = mid; else lo = mid + 1u;
    }
    return lo;
}

struct LightSample {
    vec3 wi;          // unit direction from the shading point towards the light
    float distance;   // to the light sample (kInfinity for directional lights)
    vec3 position;    // the sampled point on the light (unused for directional lights)
    vec3 radiance;    // incident radiance (area lights) or irradiance factor (delta lights)
    float pdf;        // solid-angle pdf incl. selection (area lights); selection pdf (delta lights)
    bool delta;
};

// Incident light at x from a directional, point or spot light (glTF's smooth spot falloff): a
// delta sample with pdf 1 (callers that choose lights set their selection probability).
LightSample punctualLightSample(GpuLight light, vec3 x) {
    LightSample ls;
    ls.delta = true;
    ls.pdf = 1.0f;
    if (light.type == kLightDirectional) {
        ls.wi = -light.direction;
        ls.distance = kInfinity;
        ls.position = vec3(0.0f);
        ls.radiance = light.intensity;
        return ls;
    }
    vec3 d = light.position - x;
    float dist2 = dot(d, d);
    ls.position = light.position;
    ls.distance = sqrt(dist2);
    ls.wi = d / ls.distance;
    ls.radiance = light.intensity / dist2;
    if (light.type == kLightSpot) {
        float t = clamp(dot(-ls.wi, light.direction) * light.spotScale + light.spotOffset, 0.0f, 1.0f);
        ls.radiance *= t * t;
    }
    return ls;
}

// The environment light, when the scene has one: always the last of the `lightCount` lights.
int environmentLightIndex(uint lightCount) {
    return lightCount > 0u && lights[lightCount - 1u].type == kLightEnvironment ? int(lightCount - 1u) : -1;
}

EnvironmentMap environmentMapOf(GpuLight light) {
    EnvironmentMap map;
    map.offset = light.envOffset;
    map.width = light.envWidth;
    map.height = light.envHeight;
    map.rotation = light.envRotation;
    return map;
}

// Radiance arriving from world direction d (unit) from the environment light.
vec3 environmentRadiance(GpuLight light, vec3 d) {
    if (light.envWidth == 0u) return light.intensity;
    return environmentMapRadiance(environmentMapOf(light), d);
}

// Solid-angle pdf with which sampleEnvironment returns d (without the light's selection).
float environmentPdf(GpuLight light, vec3 d) {
    if (light.envWidth == 0u || (light.envFlags & kEnvironmentSampleUniform) != 0u) return 1.0f / (4.0f * kPi);
    return environmentMapPdf(environmentMapOf(light), d);
}

// A direction towards the environment: uniform on the sphere for a constant (or with
// kEnvironmentSampleUniform), else drawn from the map's luminance x sin(theta) distribution. pdf in solid angle, without the selection.
vec3 sampleEnvironment(GpuLight light, vec2 u, out vec3 radiance, out float pdf) {
    if (light.envWidth == 0u || (light.envFlags & kEnvironmentSampleUniform) != 0u) {
        vec3 w = sampleUniformSphere(u);
        radiance = environmentRadiance(light, w);
        pdf = 1.0f / (4.0f * kPi);
        return w;
    }
    return environmentMapSample(environmentMapOf(light), u, radiance, pdf);
}

// MIS weight (power heuristic) of environment light that a BSDF-sampled ray with solid-angle pdf
// bsdfPdf found escaping along dir, against next-event estimation of the environment.
// The selection pdf is the light sampler's at the vertex the ray left (`from`, shading normal
// `fromNormal`), as next-event estimation saw it there.
float environmentMisWeight(uint lightCount, vec3 dir, float bsdfPdf, vec3 from, vec3 fromNormal) {
    int index = environmentLightIndex(lightCount);
    if (index < 0) return 1.0f;
    GpuLight light = lights[index];
    float selectPdf = selectLightPdf(lightCount, from, fromNormal, uint(index));
    return powerHeuristic(bsdfPdf, selectPdf * environmentPdf(light, dir));
}

// A sample of light `index`, chosen with probability selectPdf (shared/light_selection.glsl), as
// seen from x: emissive triangles by solid angle (where `solidAngle` allows it) or by area
// (shared/spherical_triangle.glsl).
LightSample sampleLight(uint index, float selectPdf, bool solidAngle, vec3 x, vec2 u) {
    GpuLight light = lights[index];
    if (light.type == kLightEnvironment) {
        LightSample ls;
        ls.delta = false;
        ls.distance = kInfinity;
        ls.position = vec3(0.0f);
        float pdf;
        ls.wi = sampleEnvironment(light, u, ls.radiance, pdf);
        ls.pdf = selectPdf * pdf;
        return ls;
    }
    if (light.type != kLightTriangle) {
        LightSample ls = punctualLightSample(light, x);
        ls.pdf = selectPdf;
        return ls;
    }
    LightSample ls;
    ls.delta = false;
    ls.pdf = 0.0f;
    ls.radiance = vec3(0.0f);
    GpuTriangle t = triangles[light.triangle];
    GpuTriangleShading s = shading[light.triangle];
    vec2 b;
    if (useSphericalSampling(triangleSolidAngle(t.v0.xyz, t.v1.xyz, t.v2.xyz, x), solidAngle)) {
        bool ok;
        b = sampleSphericalTriangle(t.v0.xyz, t.v1.xyz, t.v2.xyz, x, u, ok);
        if (!ok) return ls;
    } else {
        b = sampleTriangleBarycentrics(u);
    }
    vec3 p = (1.0f - b.x - b.y) * t.v0.xyz + b.x * t.v1.xyz + b.y * t.v2.xyz;
    vec3 c = cross(t.v1.xyz - t.v0.xyz, t.v2.xyz - t.v0.xyz);
    float area = 0.5f * length(c);
    vec3 ng = c / (2.0f * area);
    vec3 d = p - x;
    float dist2 = dot(d, d);
    ls.position = p;
    ls.distance = sqrt(dist2);
    ls.wi = d / ls.distance;
    float cosLight = dot(-ls.wi, ng);
    GpuMaterial m = materials[s.material];
    if (!emitsTowards(m, cosLight > 0.0f) || abs(cosLight) < 1.0e-7f || area <= 0.0f) {
        ls.pdf = 0.0f;
        return ls;
    }
    ls.radiance = emittedRadiance(m, interpolatedUv(s, b.x, b.y));
    ls.pdf = selectPdf * triangleLightPdf(t.v0.xyz, t.v1.xyz, t.v2.xyz, x, p, solidAngle);
    return ls;
}

// Visibility between a surface point (with geometric normal ng) and a light sample: the shadow
// ray leaves the surface like any other ray and stops short of the sampled point by the same
// epsilon, so neither the surface nor the light's own triangle can occlude the sample.
bool lightVisible(vec3 x, vec3 ng, LightSample ls) {
    vec3 origin = offsetRayOrigin(x, ng, ls.wi);
    vec3 dir = ls.wi;
    float tMax = kInfinity;
    if (ls.distance < kInfinity) {
        vec3 toLight = ls.position - origin;
        float distance = length(toLight);
        tMax = distance - 2.0f * rayEpsilon(ls.position);
        if (tMax <= 0.0f) return true;
        dir = toLight / distance;
    }
    // One traceAny call site: lavapipe inlines the whole traversal at each.
    return !traceAny(origin, dir, tMax);
}

#endif
