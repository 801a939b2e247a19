// Microfacet and Fresnel building blocks of the BSDF (shared/bsdf.glsl), in a local frame with +z the
// shading normal: the GGX (Trowbridge-Reitz) distribution with height-correlated Smith masking
// (Walter et al. 2007; Heitz 2014), visible-normal sampling (Heitz 2018), and the Fresnel terms
// glTF uses (Schlick's approximation; the exact dielectric Fresnel for refraction).
#ifndef VKP_BSDF_MICROFACET_GLSL
#define VKP_BSDF_MICROFACET_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

const float kMinAlpha = 1.0e-4f;

// GGX normal distribution for a local unit half vector h. Written with h's tangential part
// (hx^2 + hy^2) instead of 1 - cos^2, which keeps the sharp peak of small alphas well conditioned.
INLINE float ggxD(vec3 h, float alpha) {
    if (h.z <= 0.0f) return 0.0f;
    float a2 = alpha * alpha;
    float d = (h.x * h.x + h.y * h.y) / a2 + h.z * h.z;
    return 1.0f / (kPi * a2 * d * d);
}

INLINE float ggxLambda(vec3 w, float alpha) {
    float cos2 = w.z * w.z;
    if (cos2 <= 0.0f) return 0.0f;
    float tan2 = max(0.0f, 1.0f - cos2) / cos2;
    return 0.5f * (-1.0f + sqrt(1.0f + alpha * alpha * tan2));
}

INLINE float ggxG1(vec3 w, float alpha) {
    return 1.0f / (1.0f + ggxLambda(w, alpha));
}

// Height-correlated masking-shadowing G2(wo, wi).
INLINE float ggxG2(vec3 wo, vec3 wi, float alpha) {
    return 1.0f / (1.0f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
}

// Visible-normal sampling (Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 2018,
// listing 1) with roughness a.x along +x and a.y along +y (KHR_materials_anisotropy): stretch wo to
// the hemisphere configuration, sample the projected disk, unstretch the normal.
INLINE vec3 sampleGgxVisibleNormalAnisotropic(vec3 wo, vec2 a, vec2 u) {
    vec3 vh = normalize(vec3(a.x * wo.x, a.y * wo.y, wo.z));
    float lenSq = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = lenSq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) * inversesqrt(lenSq) : vec3(1.0f, 0.0f, 0.0f);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u.x);
    float phi = kTwoPi * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5f * (1.0f + vh.z);
    p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return normalize(vec3(a.x * nh.x, a.y * nh.y, max(1.0e-6f, nh.z)));
}

// The isotropic case (the same arithmetic with a.x = a.y = alpha).
INLINE vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
    return sampleGgxVisibleNormalAnisotropic(wo, vec2(alpha, alpha), u);
}

// Density of the visible normal h seen from wo: G1(wo) max(0, wo.h) D(h) / wo.z.
INLINE float ggxVisibleNormalPdf(vec3 wo, vec3 h, float alpha) {
    if (wo.z <= 0.0f) return 0.0f;
    return ggxG1(wo, alpha) * max(dot(wo, h), 0.0f) * ggxD(h, alpha) / wo.z;
}

// pdf of wi = reflect(wo, h) under visible-normal sampling: G1(wo) D(h) / (4 wo.z).
INLINE float ggxReflectionPdf(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    return ggxG1(wo, alpha) * ggxD(h, alpha) / (4.0f * wo.z);
}

// Appendix B's specular_brdf without Fresnel: D G2 / (4 |wo.z| |wi.z|), both above the surface.
INLINE float ggxReflection(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    return ggxD(h, alpha) * ggxG2(wo, wi, alpha) / (4.0f * wo.z * wi.z);
}

INLINE float schlickWeight(float cosTheta) {
    float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

INLINE vec3 fresnelSchlick(vec3 f0, float cosTheta) {
    return f0 + (vec3(1.0f) - f0) * schlickWeight(cosTheta);
}

// Unpolarised Fresnel reflectance of a smooth dielectric; eta = n_incident / n_transmitted.
INLINE float fresnelDielectric(float cosI, float eta) {
    cosI = clamp(cosI, 0.0f, 1.0f);
    float sin2T = eta * eta * (1.0f - cosI * cosI);
    if (sin2T >= 1.0f) return 1.0f;
    float cosT = sqrt(1.0f - sin2T);
    float rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    float rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5f * (rs * rs + rp * rp);
}

// ((ior - 1) / (ior + 1))^2; KHR_materials_ior's ior 0 gives 1 (the specular-glossiness conversion).
INLINE float dielectricF0(float ior) {
    float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

INLINE float maxComponent(vec3 v) {
    return max(v.x, max(v.y, v.z));
}

SHARED_END
#endif
