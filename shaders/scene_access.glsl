// GLSL-only scene access shared by the integrator shaders: buffer declarations, surface
// interaction at a hit, texture lookups and next-event light sampling. Bindings are the ones
// named in shared/kernels/scene.glsl.
#ifndef VKP_SCENE_ACCESS_GLSL
#define VKP_SCENE_ACCESS_GLSL

#include "shared/gpu_types.glsl"
#include "shared/kernels/scene.glsl"
#include "shared/constants.glsl"
#include "shared/sampling.glsl"
#include "shared/bsdf.glsl"

layout(std430, set = 0, binding = kSceneTrianglesBinding) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, set = 0, binding = kSceneBvhNodesBinding) readonly buffer BvhNodes { GpuBvhNode bvhNodes[]; };
layout(std430, set = 0, binding = kSceneShadingBinding) readonly buffer Shading { GpuTriangleShading shading[]; };
layout(std430, set = 0, binding = kSceneMaterialsBinding) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = kSceneLightsBinding) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = kSceneLightCdfBinding) readonly buffer LightCdf { float lightCdf[]; };
layout(std430, set = 0, binding = kSceneTexturesBinding) readonly buffer Textures { GpuTexture textures[]; };
layout(std430, set = 0, binding = kSceneTexelsBinding) readonly buffer Texels { uint texels[]; };

#include "shared/intersect.glsl"
#include "shared/bvh_traverse.glsl"
#include "shared/light_selection.glsl"
#include "shared/spherical_triangle.glsl"

// Distance by which rays leave a surface at p, scaled by p's magnitude (float spacing grows
// with it).
float rayEpsilon(vec3 p) {
    return 1.0e-4f * max(1.0f, max(abs(p.x), max(abs(p.y), abs(p.z))));
}

// Offsets shadow and continuation rays off the surface along the normal, on dir's side.
vec3 offsetRayOrigin(vec3 p, vec3 n, vec3 dir) {
    return p + (dot(dir, n) >= 0.0f ? n : -n) * rayEpsilon(p);
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : pow((c + 0.055f) / 1.055f, 2.4f);
}

vec4 texelValue(GpuTexture tex, uint x, uint y) {
    uint packed = texels[tex.offset + y * tex.width + x];
    vec4 c = unpackUnorm4x8(packed);
    if (tex.srgb != 0u) c = vec4(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a);
    return c;
}

// Bilinear lookup with repeat wrapping (glTF's default sampler).
vec4 sampleTexture(int index, vec2 uv) {
    GpuTexture tex = textures[index];
    vec2 st = uv * vec2(float(tex.width), float(tex.height)) - 0.5f;
    vec2 base = floor(st);
    vec2 f = st - base;
    int w = int(tex.width);
    int h = int(tex.height);
    uint x0 = uint(((int(base.x) % w) + w) % w);
    uint y0 = uint(((int(base.y) % h) + h) % h);
    uint x1 = (x0 + 1u) % tex.width;
    uint y1 = (y0 + 1u) % tex.height;
    vec4 a = mix(texelValue(tex, x0, y0), texelValue(tex, x1, y0), f.x);
    vec4 b = mix(texelValue(tex, x0, y1), texelValue(tex, x1, y1), f.x);
    return mix(a, b, f.y);
}

vec3 emittedRadiance(GpuMaterial m, vec2 uv) {
    vec3 e = m.emissive;
    if (m.emissiveTexture >= 0 && (e.r > 0.0f || e.g > 0.0f || e.b > 0.0f))
        e *= sampleTexture(m.emissiveTexture, uv).rgb;
    return e;
}

struct SurfaceHit {
    vec3 position;
    vec3 geometricNormal;   // unit, from the winding (front face side)
    vec3 shadingNormal;     // unit, interpolated, flipped to the geometric normal's side
    vec2 uv;
    uint material;
    float emitterPdfArea;
    bool frontFace;         // the ray arrived on the front (counter-clockwise) side
    uint triangle;          // index in BVH order
};

SurfaceHit surfaceAt(uint tri, float b1, float b2, vec3 rayDir) {
    GpuTriangle t = triangles[tri];
    GpuTriangleShading s = shading[tri];
    float b0 = 1.0f - b1 - b2;
    SurfaceHit hit;
    hit.position = b0 * t.v0.xyz + b1 * t.v1.xyz + b2 * t.v2.xyz;
    hit.geometricNormal = normalize(cross(t.v1.xyz - t.v0.xyz, t.v2.xyz - t.v0.xyz));
    vec3 n = b0 * s.n0.xyz + b1 * s.n1.xyz + b2 * s.n2.xyz;
    float len = length(n);
    n = len > 0.0f ? n / len : hit.geometricNormal;
    if (dot(n, hit.geometricNormal) < 0.0f) n = -n;
    hit.shadingNormal = n;
    hit.uv = b0 * s.uv01.xy + b1 * s.uv01.zw + b2 * s.uv2;
    hit.material = s.material;
    hit.emitterPdfArea = s.emitterPdfArea;
    hit.frontFace = dot(rayDir, hit.geometricNormal) < 0.0f;
    hit.triangle = tri;
    return hit;
}

BsdfParams bsdfParamsAt(GpuMaterial m, vec2 uv) {
    BsdfParams p;
    vec4 base = m.baseColor;
    if (m.baseColorTexture >= 0) base *= sampleTexture(m.baseColorTexture, uv);
    float metallic = m.metallic;
    float roughness = m.roughness;
    if (m.metallicRoughnessTexture >= 0) {
        vec4 mr = sampleTexture(m.metallicRoughnessTexture, uv);
        roughness *= mr.g;  // glTF: roughness in G, metalness in B
        metallic *= mr.b;
    }
    p.baseColor = base.rgb;
    p.metallic = clamp(metallic, 0.0f, 1.0f);
    p.roughness = clamp(roughness, 0.0f, 1.0f);
    p.transmission = clamp(m.transmission, 0.0f, 1.0f);
    p.ior = max(m.ior, 1.0f);
    p.thinWalled = (m.flags & kMaterialThinWalled) != 0u ? 1u : 0u;
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

// A sample of light `index`, chosen with probability selectPdf (shared/light_selection.glsl), as
// seen from x: emissive triangles by solid angle (where `solidAngle` allows it) or by area
// (shared/spherical_triangle.glsl).
LightSample sampleLight(uint index, float selectPdf, bool solidAngle, vec3 x, vec2 u) {
    GpuLight light = lights[index];
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
    vec2 uv = (1.0f - b.x - b.y) * s.uv01.xy + b.x * s.uv01.zw + b.y * s.uv2;
    ls.radiance = emittedRadiance(m, uv);
    ls.pdf = selectPdf * triangleLightPdf(t.v0.xyz, t.v1.xyz, t.v2.xyz, x, p, solidAngle);
    return ls;
}

// Visibility between a surface point (with geometric normal ng) and a light sample: the shadow
// ray leaves the surface like any other ray and stops short of the sampled point by the same
// epsilon, so neither the surface nor the light's own triangle can occlude the sample.
bool lightVisible(vec3 x, vec3 ng, LightSample ls) {
    vec3 origin = offsetRayOrigin(x, ng, ls.wi);
    if (ls.distance >= kInfinity) return !traceAny(origin, ls.wi, kInfinity);
    vec3 toLight = ls.position - origin;
    float distance = length(toLight);
    float tMax = distance - 2.0f * rayEpsilon(ls.position);
    return tMax <= 0.0f || !traceAny(origin, toLight / distance, tMax);
}

#endif
