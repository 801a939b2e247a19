// The rough dielectric layer of KHR_materials_transmission (roughness >= kDeltaRoughness): GGX
// microfacet reflection and transmission (Walter, Marschner, Li, Torrance 2007, "Microfacet Models
// for Refraction through Rough Surfaces"), local frame with wo.z > 0. docs/materials.md has the
// formulas. eta = n(wo side) / n(other side), as shared/bsdf.glsl's sampleDielectric.
//  - reflection (wi.z > 0):  f = F(wo.m) D(m) G2 / (4 wo.z wi.z),  m = normalize(wo + wi)
//  - solid transmission:     f = s (1 - F(wo.m)) D(m) G2 |wi.m| |wo.m| / (wo.z |wi.z| (wi.m + eta wo.m)^2)
//      m = -normalize(eta wo + wi) (Walter's generalized half vector, flipped to m.z > 0),
//      s = eta^2 for radiance (camera paths), 1 for importance (photons): the adjoint BTDF
//      (Veach 1997, section 5.2): radiance is compressed by (n_t / n_i)^2 when it enters a denser
//      medium, importance is not.
//  - thin-walled transmission (glTF's thin-wall model, no net bending): the reflection lobe
//      mirrored through the surface, f(wo, wi) = (1 - F(wo.m)) D(m) G2 / (4 wo.z |wi.z|) with
//      m = normalize(wo + (wi.x, wi.y, -wi.z)).
// Transmission is tinted by baseColor (the callers multiply). Sampling: visible normals (Heitz
// 2018), then Fresnel picks reflection or transmission, so every sample weighs G2 / G1(wo) (times
// s and the tint for transmission) and the pdf is F or 1 - F times the visible-normal density
// times the half-vector Jacobian (1 / (4 |wo.m|) for reflection, |wi.m| / (wi.m + eta wo.m)^2
// for refraction).
// Under KHR_materials_iridescence's film (seen from outside) the microfacet Fresnel is a colour,
// F = mix(F_plain, thin-film F, weight) per channel (the film and the base are non-absorbing, so
// what it does not reflect it transmits): reflection is chosen with the mean P of F's channels, so
// the pdf is P or 1 - P times the same densities, and the weights are G2 / G1(wo) times F / P or
// (1 - F) / (1 - P) (the *Film functions below).
#ifndef VKP_BSDF_ROUGH_DIELECTRIC_GLSL
#define VKP_BSDF_ROUGH_DIELECTRIC_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "bsdf_microfacet.glsl"
#include "bsdf_iridescence.glsl"
SHARED_BEGIN

// The microfacet normal that takes wo to wi (either side); returns false when none does (wi on
// the wrong side of m for the event, or a degenerate configuration).
INLINE bool roughDielectricHalfVector(vec3 wo, vec3 wi, float eta, bool thin, OUT(vec3) m) {
    if (wo.z <= 0.0f || wi.z == 0.0f) return false;
    if (wi.z > 0.0f || thin) {
        vec3 wr = vec3(wi.x, wi.y, abs(wi.z));
        vec3 s = wo + wr;
        if (dot(s, s) <= 1.0e-12f) return false;
        m = normalize(s);
        return true;
    }
    vec3 s = -(eta * wo + wi);
    if (dot(s, s) <= 1.0e-12f) return false;
    m = normalize(s);
    if (m.z < 0.0f) m = -m;
    // Refraction needs wo and wi on opposite sides of the microfacet.
    return dot(wo, m) > 0.0f && dot(wi, m) < 0.0f;
}

INLINE float roughDielectricFresnel(float cosOM, float eta, bool infiniteIor) {
    return infiniteIor ? 1.0f : fresnelDielectric(cosOM, eta);
}

// f (no cosine, no tint) for wo.z > 0 and wi on either side.
INLINE float evalRoughDielectric(vec3 wo, vec3 wi, float alpha, float eta, bool thin, bool infiniteIor,
                                 bool radiance) {
    vec3 m;
    if (!roughDielectricHalfVector(wo, wi, eta, thin, m)) return 0.0f;
    float cosOM = dot(wo, m);
    if (cosOM <= 0.0f) return 0.0f;
    float fr = roughDielectricFresnel(cosOM, eta, infiniteIor);
    float dg = ggxD(m, alpha) * ggxG2(wo, wi, alpha);
    if (wi.z > 0.0f) return fr * dg / (4.0f * wo.z * wi.z);
    if (thin) return (1.0f - fr) * dg / (4.0f * wo.z * -wi.z);
    float cosIM = dot(wi, m);
    float denom = cosIM + eta * cosOM;
    float f = (1.0f - fr) * dg * abs(cosIM) * cosOM / (wo.z * -wi.z * denom * denom);
    return radiance ? f * eta * eta : f;
}

// The density of wi through half vector m (cosOM = dot(wo, m) > 0) when reflection is chosen with
// probability pr: the visible normal's density times the reflection's or refraction's Jacobian.
INLINE float roughDielectricPdfAt(vec3 wo, vec3 wi, vec3 m, float cosOM, float pr, float alpha, float eta, bool thin) {
    float pm = ggxVisibleNormalPdf(wo, m, alpha);
    if (wi.z > 0.0f) return pr * pm / (4.0f * cosOM);
    if (thin) return (1.0f - pr) * pm / (4.0f * cosOM);
    float cosIM = dot(wi, m);
    float denom = cosIM + eta * cosOM;
    return (1.0f - pr) * pm * abs(cosIM) / (denom * denom);
}

// Solid-angle density with which sampleRoughDielectric produces wi.
INLINE float pdfRoughDielectric(vec3 wo, vec3 wi, float alpha, float eta, bool thin, bool infiniteIor) {
    vec3 m;
    if (!roughDielectricHalfVector(wo, wi, eta, thin, m)) return 0.0f;
    float cosOM = dot(wo, m);
    if (cosOM <= 0.0f) return 0.0f;
    return roughDielectricPdfAt(wo, wi, m, cosOM, roughDielectricFresnel(cosOM, eta, infiniteIor), alpha, eta, thin);
}

// Samples the rough dielectric: u.x picks reflection or transmission by Fresnel, u.yz the visible
// normal. Returns wi (z = 0 when the sample failed) and in weight the sample weight f |wi.z| / pdf
// without the tint: G2 / G1(wo), times eta^2 for radiance through a solid's interface.
INLINE vec3 sampleRoughDielectric(vec3 wo, float alpha, float eta, bool thin, bool infiniteIor, bool radiance,
                                  vec3 u, OUT(float) weight) {
    weight = 0.0f;
    if (wo.z <= 0.0f) return vec3(0.0f);
    vec3 m = sampleGgxVisibleNormal(wo, alpha, vec2(u.y, u.z));
    float cosOM = dot(wo, m);
    if (cosOM <= 0.0f) return vec3(0.0f);
    float fr = roughDielectricFresnel(cosOM, eta, infiniteIor);
    vec3 wi;
    if (u.x < fr || thin) {
        wi = 2.0f * cosOM * m - wo;
        if (wi.z <= 0.0f) return vec3(0.0f);
        if (u.x >= fr) wi.z = -wi.z;  // thin wall: the mirrored reflection on the other side
    } else {
        float sin2T = eta * eta * (1.0f - cosOM * cosOM);
        if (sin2T >= 1.0f) return vec3(0.0f);  // unreachable: fr = 1 under total internal reflection
        float cosT = sqrt(1.0f - sin2T);
        wi = (eta * cosOM - cosT) * m - eta * wo;
        if (wi.z >= 0.0f) return vec3(0.0f);
        wi = normalize(wi);
    }
    weight = ggxG2(wo, wi, alpha) / ggxG1(wo, alpha);
    if (radiance && !thin && wi.z < 0.0f) weight *= eta * eta;
    return wi;
}

// The film over the rough dielectric: film = (weight, film ior, thickness in nm, the base's F0), seen
// from outside (eta = 1 / ior < 1). The microfacet Fresnel per channel, in [0, 1].
INLINE vec3 roughDielectricFilmFresnel(float cosOM, float eta, vec4 film) {
    return clamp(mix(vec3(fresnelDielectric(cosOM, eta)), thinFilmFresnel(1.0f, film.y, cosOM, film.z, vec3(film.w)), film.x),
                 vec3(0.0f), vec3(1.0f));
}

// The probability of sampling reflection for the colour Fresnel f: the mean of its channels, kept
// off 0 and 1 so that neither branch is dropped where it carries light.
INLINE float roughDielectricFilmReflectProbability(vec3 f) {
    return clamp((f.x + f.y + f.z) * (1.0f / 3.0f), 1.0e-4f, 1.0f - 1.0e-4f);
}

// f (no cosine, no tint) per channel under the film, as evalRoughDielectric.
INLINE vec3 evalRoughDielectricFilm(vec3 wo, vec3 wi, float alpha, float eta, bool thin, bool radiance, vec4 film) {
    vec3 m;
    if (!roughDielectricHalfVector(wo, wi, eta, thin, m)) return vec3(0.0f);
    float cosOM = dot(wo, m);
    if (cosOM <= 0.0f) return vec3(0.0f);
    vec3 fr = roughDielectricFilmFresnel(cosOM, eta, film);
    float dg = ggxD(m, alpha) * ggxG2(wo, wi, alpha);
    if (wi.z > 0.0f) return fr * (dg / (4.0f * wo.z * wi.z));
    if (thin) return (vec3(1.0f) - fr) * (dg / (4.0f * wo.z * -wi.z));
    float cosIM = dot(wi, m);
    float denom = cosIM + eta * cosOM;
    vec3 f = (vec3(1.0f) - fr) * (dg * abs(cosIM) * cosOM / (wo.z * -wi.z * denom * denom));
    return radiance ? f * (eta * eta) : f;
}

// Solid-angle density with which sampleRoughDielectricFilm produces wi.
INLINE float pdfRoughDielectricFilm(vec3 wo, vec3 wi, float alpha, float eta, bool thin, vec4 film) {
    vec3 m;
    if (!roughDielectricHalfVector(wo, wi, eta, thin, m)) return 0.0f;
    float cosOM = dot(wo, m);
    if (cosOM <= 0.0f) return 0.0f;
    float pr = roughDielectricFilmReflectProbability(roughDielectricFilmFresnel(cosOM, eta, film));
    return roughDielectricPdfAt(wo, wi, m, cosOM, pr, alpha, eta, thin);
}

// Samples the rough dielectric under the film: u.x picks reflection with probability P (the mean of
// the colour Fresnel), u.yz the visible normal. weight = f |wi.z| / pdf per channel, without the tint.
INLINE vec3 sampleRoughDielectricFilm(vec3 wo, float alpha, float eta, bool thin, bool radiance, vec4 film, vec3 u,
                                      OUT(vec3) weight) {
    weight = vec3(0.0f);
    if (wo.z <= 0.0f) return vec3(0.0f);
    vec3 m = sampleGgxVisibleNormal(wo, alpha, vec2(u.y, u.z));
    float cosOM = dot(wo, m);
    if (cosOM <= 0.0f) return vec3(0.0f);
    vec3 fr = roughDielectricFilmFresnel(cosOM, eta, film);
    float pr = roughDielectricFilmReflectProbability(fr);
    bool reflected = u.x < pr;
    vec3 wi;
    if (reflected || thin) {
        wi = 2.0f * cosOM * m - wo;
        if (wi.z <= 0.0f) return vec3(0.0f);
        if (!reflected) wi.z = -wi.z;  // thin wall: the mirrored reflection on the other side
    } else {
        float sin2T = eta * eta * (1.0f - cosOM * cosOM);
        if (sin2T >= 1.0f) return vec3(0.0f);  // no total internal reflection seen from outside (eta < 1)
        float cosT = sqrt(1.0f - sin2T);
        wi = (eta * cosOM - cosT) * m - eta * wo;
        if (wi.z >= 0.0f) return vec3(0.0f);
        wi = normalize(wi);
    }
    float g = ggxG2(wo, wi, alpha) / ggxG1(wo, alpha);
    weight = reflected ? fr * (g / pr) : (vec3(1.0f) - fr) * (g / (1.0f - pr));
    if (radiance && !thin && !reflected) weight = weight * (eta * eta);
    return wi;
}

SHARED_END
#endif
