// KHR_materials_sheen: the "Charlie" sheen lobe (Estevez & Kulla 2017, "Production Friendly
// Microfacet Sheen BRDF") as the extension specifies it, in the local frame of shared/bsdf.glsl:
//   sheen_brdf = sheenColor * D(alpha, NdotH) * V(NdotV, NdotL)
//   D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi),      alpha = sheenRoughness^2
//   V = 1 / ((1 + Lambda(NdotV) + Lambda(NdotL)) 4 NdotV NdotL)   (the extension's fitted Lambda)
// and the layering: f = sheen_brdf + f_base * min(1 - max(sheenColor) E(NdotV), 1 - max(sheenColor) E(NdotL)),
// E the directional albedo of the white sheen lobe (shared/bsdf_tables.glsl kSheenAlbedo).
#ifndef VKP_BSDF_SHEEN_GLSL
#define VKP_BSDF_SHEEN_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

// The smallest sheen alpha vkphoton evaluates (sheenRoughness ~0.03): below it D is a spike at
// grazing half vectors that float precision cannot represent.
const float kMinSheenAlpha = 1.0e-3f;

INLINE float sheenAlpha(float sheenRoughness) {
    return max(sheenRoughness * sheenRoughness, kMinSheenAlpha);
}

INLINE float charlieD(float alpha, float cosH) {
    float invAlpha = 1.0f / alpha;
    float sin2h = max(1.0f - cosH * cosH, 0.0f);
    return (2.0f + invAlpha) * pow(sin2h, 0.5f * invAlpha) / kTwoPi;
}

INLINE float charlieL(float x, float alpha) {
    float t = (1.0f - alpha) * (1.0f - alpha);
    float a = mix(21.5473f, 25.3245f, t);
    float b = mix(3.82987f, 3.32435f, t);
    float c = mix(0.19823f, 0.16801f, t);
    float d = mix(-1.97760f, -1.27393f, t);
    float e = mix(-4.32054f, -4.85967f, t);
    return a / (1.0f + b * pow(x, c)) + d * x + e;
}

INLINE float charlieLambda(float cosTheta, float alpha) {
    if (abs(cosTheta) < 0.5f) return exp(charlieL(abs(cosTheta), alpha));
    return exp(2.0f * charlieL(0.5f, alpha) - charlieL(1.0f - abs(cosTheta), alpha));
}

// The white sheen lobe D V (no colour) for local wo, wi above the surface.
INLINE float charlieSheen(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    float v = 1.0f / ((1.0f + charlieLambda(wo.z, alpha) + charlieLambda(wi.z, alpha)) * 4.0f * wo.z * wi.z);
    return charlieD(alpha, h.z) * v;
}

SHARED_END
#endif
