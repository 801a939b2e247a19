// The glTF metallic-roughness BSDF in a local frame (+z = shading normal on the side of wo):
//  - opaque layer: Lambert diffuse ((1 - metallic) * baseColor, weighted by the dielectric's
//    transmitted fraction (1 - F(wo))(1 - F(wi)), which keeps it reciprocal) plus a GGX microfacet
//    specular lobe (Walter et al. 2007; height-correlated Smith masking; visible-normal sampling,
//    Heitz 2018) whose Fresnel term mixes the exact dielectric Fresnel of `ior` with Schlick's
//    approximation from F0 = baseColor for metals by `metallic`. With ior = 1 and metallic = 0
//    the surface is exactly Lambertian (the furnace tests rely on it).
//    Roughness below kDeltaRoughness becomes a perfect mirror.
//  - with probability `transmission` (KHR_materials_transmission) the hit is instead a smooth
//    dielectric: exact Fresnel picks reflection or refraction (tinted by baseColor); thin-walled
//    surfaces transmit straight through.
#ifndef VKP_BSDF_GLSL
#define VKP_BSDF_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "sampling.glsl"
SHARED_BEGIN

const float kMinAlpha = 1.0e-4f;
const float kDeltaRoughness = 0.02f;  // perceptual roughness below which the specular is a mirror

const uint kLobeNone = 0u;
const uint kLobeDiffuse = 1u;
const uint kLobeGlossy = 2u;
const uint kLobeDelta = 4u;          // a Dirac lobe: pdf is not a density, excluded from MIS
const uint kLobeTransmission = 8u;

struct BsdfParams {
    vec3 baseColor;
    float metallic;
    float roughness;      // perceptual; alpha = roughness^2
    float transmission;
    float ior;
    uint thinWalled;      // 1: transmission goes straight through (no KHR_materials_volume)
};

struct BsdfSample {
    vec3 wi;              // local sampled direction
    vec3 weight;          // f * |cos| / pdf (delta lobes: the lobe's reflectance / probability)
    float pdf;            // solid-angle pdf of wi under the whole BSDF; 0 for delta lobes
    uint lobe;
};

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

// Visible-normal sampling (Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 2018).
INLINE vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
    vec3 vh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
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
    return normalize(vec3(alpha * nh.x, alpha * nh.y, max(1.0e-6f, nh.z)));
}

// pdf of wi = reflect(wo, h) under visible-normal sampling: G1(wo) D(h) / (4 wo.z).
INLINE float ggxReflectionPdf(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    return ggxG1(wo, alpha) * ggxD(h, alpha) / (4.0f * wo.z);
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

INLINE float dielectricF0(float ior) {
    float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

INLINE float bsdfAlpha(BsdfParams p) {
    return max(p.roughness * p.roughness, kMinAlpha);
}

INLINE bool specularIsDelta(BsdfParams p) {
    return p.roughness < kDeltaRoughness;
}

// Fresnel reflectance of the opaque layer's specular lobe at cos(wo, h).
INLINE vec3 specularFresnel(BsdfParams p, float cosTheta) {
    float dielectric = fresnelDielectric(cosTheta, 1.0f / p.ior);
    return mix(vec3(dielectric), fresnelSchlick(p.baseColor, cosTheta), p.metallic);
}

// Fraction of light that passes the dielectric coating into the diffuse base.
INLINE float diffuseTransmittance(BsdfParams p, float cosTheta) {
    return 1.0f - fresnelDielectric(cosTheta, 1.0f / p.ior);
}

INLINE vec3 diffuseAlbedo(BsdfParams p) {
    return (1.0f - p.metallic) * p.baseColor;
}

// Probability of sampling the specular lobe of the opaque layer, from estimated lobe albedos.
INLINE float specularSelectProbability(BsdfParams p, float cosO) {
    float spec = luminance(specularFresnel(p, cosO));
    float diff = luminance(diffuseAlbedo(p)) * diffuseTransmittance(p, cosO);
    if (diff <= 0.0f) return 1.0f;
    if (spec <= 0.0f) return 0.0f;
    return clamp(spec / (spec + diff), 0.1f, 0.9f);
}

// Below this perceptual roughness a metal's glossy lobe is too narrow for photon density
// estimation: photon paths, camera paths and final gather rays follow it like a mirror.
const float kPhotonGlossyRoughness = 0.2f;

// The surface scatters light diffusely or broadly enough for photon estimates: it stores photons,
// becomes a visible point and ends a final gather ray. Otherwise (smooth glass, mirrors, polished
// metal) paths go on through it and photons that left it are caustic photons.
INLINE bool storesPhotons(BsdfParams p) {
    bool mirrorLike = p.metallic >= 1.0f && (specularIsDelta(p) || p.roughness < kPhotonGlossyRoughness);
    return p.transmission < 1.0f && !mirrorLike;
}

// Non-delta part of the BSDF (f, without the cosine) for local wo, wi; both on the +z side.
INLINE vec3 evalBsdf(BsdfParams p, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
    vec3 f = diffuseAlbedo(p) * (kInvPi * diffuseTransmittance(p, wo.z) * diffuseTransmittance(p, wi.z));
    if (!specularIsDelta(p)) {
        float alpha = bsdfAlpha(p);
        vec3 h = normalize(wo + wi);
        float g2 = 1.0f / (1.0f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
        vec3 fr = specularFresnel(p, dot(wo, h));
        f = f + fr * (ggxD(h, alpha) * g2 / (4.0f * wo.z * wi.z));
    }
    return f * (1.0f - p.transmission);
}

// The diffuse part of the BSDF for light arriving along the normal: what turns precomputed
// irradiance into reflected radiance (Christensen's radiance photons; the glossy part of the
// surface is left out).
INLINE vec3 diffuseReflectance(BsdfParams p, vec3 wo) {
    if (wo.z <= 0.0f) return vec3(0.0f);
    return diffuseAlbedo(p) * (kInvPi * diffuseTransmittance(p, wo.z) * diffuseTransmittance(p, 1.0f)) *
           (1.0f - p.transmission);
}

// Solid-angle pdf with which sampleBsdf produces wi through its non-delta lobes.
INLINE float pdfBsdf(BsdfParams p, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float pSpec = specularSelectProbability(p, wo.z);
    float pdf = (1.0f - pSpec) * cosineHemispherePdf(wi.z);
    if (!specularIsDelta(p)) pdf = pdf + pSpec * ggxReflectionPdf(wo, wi, bsdfAlpha(p));
    return pdf * (1.0f - p.transmission);
}

// Samples the smooth dielectric layer. `entering`: wo is on the outside of the surface.
// `radiance`: scale refracted throughput by eta^2 (camera paths), not for photons (importance).
INLINE BsdfSample sampleDielectric(BsdfParams p, vec3 wo, bool entering, bool radiance, vec2 u) {
    BsdfSample s;
    s.pdf = 0.0f;
    float eta = entering ? 1.0f / p.ior : p.ior;
    if (p.thinWalled != 0u) eta = 1.0f / p.ior;
    float fr = fresnelDielectric(wo.z, eta);
    if (u.x < fr) {
        s.wi = vec3(-wo.x, -wo.y, wo.z);
        s.weight = vec3(1.0f);
        s.lobe = kLobeDelta;
        return s;
    }
    s.lobe = kLobeDelta | kLobeTransmission;
    s.weight = p.baseColor;
    if (p.thinWalled != 0u) {
        s.wi = -wo;
        return s;
    }
    float cosT = sqrt(max(0.0f, 1.0f - eta * eta * (1.0f - wo.z * wo.z)));
    s.wi = normalize(vec3(-eta * wo.x, -eta * wo.y, -cosT));
    if (radiance) s.weight = s.weight * (eta * eta);
    return s;
}

// Samples the whole BSDF: u.x picks the layer (and, rescaled, the opaque lobe), u.yz the direction.
INLINE BsdfSample sampleBsdf(BsdfParams p, vec3 wo, bool entering, bool radiance, vec3 u) {
    if (u.x < p.transmission) {
        return sampleDielectric(p, wo, entering, radiance, vec2(u.y, u.z));
    }
    BsdfSample s;
    s.lobe = kLobeNone;
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    s.wi = vec3(0.0f, 0.0f, 1.0f);
    if (wo.z <= 0.0f) return s;
    float pSpec = specularSelectProbability(p, wo.z);
    float uLobe = (u.x - p.transmission) / max(1.0f - p.transmission, 1.0e-6f);
    bool delta = specularIsDelta(p);
    if (uLobe < pSpec) {
        if (delta) {
            s.wi = vec3(-wo.x, -wo.y, wo.z);
            s.weight = specularFresnel(p, wo.z) / pSpec;
            s.lobe = kLobeDelta;
            return s;
        }
        vec3 h = sampleGgxVisibleNormal(wo, bsdfAlpha(p), vec2(u.y, u.z));
        s.wi = reflect(-wo, h);
        s.lobe = kLobeGlossy;
    } else {
        s.wi = sampleCosineHemisphere(vec2(u.y, u.z));
        s.lobe = kLobeDiffuse;
    }
    if (s.wi.z <= 0.0f) {
        s.lobe = kLobeNone;
        return s;
    }
    // Both non-delta lobes could have produced wi: weight by the full mixture pdf (delta
    // specular excluded, it has probability zero of producing this direction).
    s.pdf = pdfBsdf(p, wo, s.wi);
    if (s.pdf <= 0.0f) {
        s.lobe = kLobeNone;
        return s;
    }
    s.weight = evalBsdf(p, wo, s.wi) * s.wi.z / s.pdf;
    return s;
}

SHARED_END
#endif
