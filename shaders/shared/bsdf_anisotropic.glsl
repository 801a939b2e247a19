// Anisotropic GGX for KHR_materials_anisotropy, in a local frame with +z the shading normal and +x
// the anisotropy direction (the BSDF rotates into it, bsdf.glsl anisotropicFrame): the
// distribution D(h) = 1 / (pi ax ay (hx^2/ax^2 + hy^2/ay^2 + hz^2)^2), its height-correlated Smith
// masking with Lambda(w) = (-1 + sqrt(1 + (ax^2 wx^2 + ay^2 wy^2) / wz^2)) / 2, and its pdf under
// visible-normal sampling (sampleGgxVisibleNormalAnisotropic, bsdf_microfacet.glsl). The isotropic
// functions of bsdf_microfacet.glsl stay separate: a material without anisotropy runs exactly the
// code it ran before (sampling included: the isotropic sampler is the same arithmetic).
#ifndef VKP_BSDF_ANISOTROPIC_GLSL
#define VKP_BSDF_ANISOTROPIC_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "bsdf_microfacet.glsl"
SHARED_BEGIN

// The extension's roughnesses: along the anisotropy direction alpha_t = mix(alpha, 1, strength^2),
// across it alpha_b = alpha (both at least 1e-3, as the Khronos sample renderer clamps alpha_b:
// a lobe that is a line cannot be sampled against next-event estimation).
INLINE vec2 anisotropicAlphas(float alpha, float strength) {
    float ab = clamp(alpha, 1.0e-3f, 1.0f);
    float at = max(mix(alpha, 1.0f, strength * strength), ab);
    return vec2(at, ab);
}

INLINE float ggxDAnisotropic(vec3 h, vec2 a) {
    if (h.z <= 0.0f) return 0.0f;
    float x = h.x / a.x;
    float y = h.y / a.y;
    float d = x * x + y * y + h.z * h.z;
    return 1.0f / (kPi * a.x * a.y * d * d);
}

INLINE float ggxLambdaAnisotropic(vec3 w, vec2 a) {
    float cos2 = w.z * w.z;
    if (cos2 <= 0.0f) return 0.0f;
    float t2 = (a.x * a.x * w.x * w.x + a.y * a.y * w.y * w.y) / cos2;
    return 0.5f * (-1.0f + sqrt(1.0f + t2));
}

INLINE float ggxG1Anisotropic(vec3 w, vec2 a) {
    return 1.0f / (1.0f + ggxLambdaAnisotropic(w, a));
}

INLINE float ggxG2Anisotropic(vec3 wo, vec3 wi, vec2 a) {
    return 1.0f / (1.0f + ggxLambdaAnisotropic(wo, a) + ggxLambdaAnisotropic(wi, a));
}

// pdf of wi = reflect(wo, h) under visible-normal sampling: G1(wo) D(h) / (4 wo.z).
INLINE float ggxReflectionPdfAnisotropic(vec3 wo, vec3 wi, vec2 a) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    return ggxG1Anisotropic(wo, a) * ggxDAnisotropic(h, a) / (4.0f * wo.z);
}

// specular_brdf without Fresnel: D G2 / (4 wo.z wi.z), both above the surface.
INLINE float ggxReflectionAnisotropic(vec3 wo, vec3 wi, vec2 a) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    return ggxDAnisotropic(h, a) * ggxG2Anisotropic(wo, wi, a) / (4.0f * wo.z * wi.z);
}

SHARED_END
#endif
