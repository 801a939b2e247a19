// The glTF 2.0 material BSDF (Appendix B and the KHR_materials_* extensions vkphoton reads) in a
// local frame (+z = shading normal on the side of wo). docs/materials.md has the formulas.
//  - opaque layer, glTF Appendix B with KHR_materials_specular and KHR_materials_ior:
//      f = (1 - metallic) * dielectric + metallic * metal
//      dielectric = (1 - max(Fd)) * baseColor / pi + Fd * specular_brdf
//      metal      = Fm * specular_brdf
//    with Fd = specular * (f0 + (1 - f0) (1 - VdotH)^5), f0 = min(((ior-1)/(ior+1))^2 specularColor, 1),
//    Fm = baseColor + (1 - baseColor)(1 - VdotH)^5 (Schlick), and specular_brdf the GGX microfacet
//    reflection D G2 / (4 |NdotL| |NdotV|) (shared/bsdf_microfacet.glsl). specular = 0 is exactly
//    Lambert. Roughness below kDeltaRoughness makes the specular lobe a perfect mirror.
//    KHR_materials_anisotropy stretches that lobe along anisotropyDirection (bsdf_anisotropic.glsl);
//    KHR_materials_iridescence mixes a thin film's Fresnel into Fd and Fm (bsdf_iridescence.glsl).
//  - with probability `transmission` (KHR_materials_transmission) the hit is instead a dielectric:
//    smooth (roughness < kDeltaRoughness): exact Fresnel picks reflection or refraction (tinted by
//    baseColor), thin-walled surfaces transmit straight through; rough: the GGX BSDF of Walter et al.
//    2007 (shared/bsdf_rough_dielectric.glsl); both under KHR_materials_iridescence's film when seen
//    from outside (a colour Fresnel). The dielectric layer is sampled, not evaluated:
//    its samples carry kLobeDelta (no light sampling, no MIS), see sampleBsdf.
// One code path for evaluation, sampling and pdf: sampling picks a lobe with a probability from
// the lobes' estimated albedos at wo (bsdfLobeProbabilities), and returns the mixture pdf.
#ifndef VKP_BSDF_GLSL
#define VKP_BSDF_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "sampling.glsl"
#include "bsdf_microfacet.glsl"
#include "bsdf_anisotropic.glsl"
#include "bsdf_iridescence.glsl"
#include "bsdf_sheen.glsl"
#include "bsdf_rough_dielectric.glsl"
#include "bsdf_tables.glsl"  // GLSL: a storage buffer (VKP_BSDF_TABLES_BINDING)
SHARED_BEGIN

const float kDeltaRoughness = 0.02f;  // perceptual roughness below which the specular is a mirror

const uint kLobeNone = 0u;
const uint kLobeDiffuse = 1u;
const uint kLobeGlossy = 2u;
const uint kLobeDelta = 4u;          // a Dirac lobe: pdf is not a density, excluded from MIS
const uint kLobeTransmission = 8u;
// A sample of the rough dielectric layer: kLobeDelta for the kernels that take it at full weight
// (photons, importons, final gathers), and with this bit the camera-path integrators know it has
// a density (pdfDielectricLayer) to weigh it against next-event estimation with.
const uint kLobeLayer = 16u;

const uint kBsdfNoEnergyCompensation = 1u;  // BsdfParams.flags: the spec's plain single-scattering GGX
// BsdfParams.flags: the coat has its own normal, clearcoatNormal (KHR_materials_clearcoat's
// clearcoatNormalTexture, or the unmapped surface normal under a base normal map).
const uint kBsdfCoatNormal = 2u;

// Everything the BSDF reads at one surface point (material factors x textures). Fields after
// thinWalled are appended for KHR_materials_specular/sheen/clearcoat; construct with
// makeBsdfParams so that they start at the glTF defaults.
struct BsdfParams {
    vec3 baseColor;
    float metallic;
    float roughness;      // perceptual; alpha = roughness^2
    float transmission;
    float ior;
    uint thinWalled;      // 1: transmission goes straight through (no KHR_materials_volume)
    vec3 specularColor;   // KHR_materials_specular: specularColorFactor x texture (F0 colour)
    float specular;       // KHR_materials_specular: specularFactor x texture (weight, F90)
    vec3 sheenColor;      // KHR_materials_sheen (later; zero = no sheen)
    float sheenRoughness;
    float clearcoat;      // KHR_materials_clearcoat (later; zero = no coat)
    float clearcoatRoughness;
    uint flags;           // kBsdf* bits
    float anisotropy;     // KHR_materials_anisotropy strength (zero = isotropic)
    vec3 clearcoatNormal; // the coat's unit normal in the local frame; +z unless kBsdfCoatNormal
    float iridescence;    // KHR_materials_iridescence factor (zero = no thin film)
    vec2 anisotropyDirection;    // unit, in the local xy plane: where the lobe is stretched
    float iridescenceIor;        // the film's index of refraction
    float iridescenceThickness;  // the film's thickness in nanometres (zero = no film)
};
STATIC_ASSERT_SIZE(BsdfParams, 112)

// The glTF defaults: a rough white dielectric of ior 1.5 with full specular, no extensions.
INLINE BsdfParams makeBsdfParams(vec3 baseColor, float metallic, float roughness) {
    BsdfParams p;
    p.baseColor = baseColor;
    p.metallic = metallic;
    p.roughness = roughness;
    p.transmission = 0.0f;
    p.ior = 1.5f;
    p.thinWalled = 0u;
    p.specularColor = vec3(1.0f);
    p.specular = 1.0f;
    p.sheenColor = vec3(0.0f);
    p.sheenRoughness = 0.0f;
    p.clearcoat = 0.0f;
    p.clearcoatRoughness = 0.0f;
    p.flags = 0u;
    p.anisotropy = 0.0f;
    p.clearcoatNormal = vec3(0.0f, 0.0f, 1.0f);
    p.iridescence = 0.0f;
    p.anisotropyDirection = vec2(1.0f, 0.0f);
    p.iridescenceIor = 1.3f;
    p.iridescenceThickness = 0.0f;
    return p;
}

struct BsdfSample {
    vec3 wi;              // local sampled direction
    vec3 weight;          // f * |cos| / pdf (delta lobes: the lobe's reflectance / probability)
    float pdf;            // solid-angle pdf of wi under the whole BSDF; 0 for delta lobes
    uint lobe;
};

INLINE float bsdfAlpha(BsdfParams p) {
    return max(p.roughness * p.roughness, kMinAlpha);
}

INLINE float clearcoatAlpha(BsdfParams p) {
    return max(p.clearcoatRoughness * p.clearcoatRoughness, kMinAlpha);
}

INLINE bool specularIsDelta(BsdfParams p) {
    return p.roughness < kDeltaRoughness;
}

INLINE bool isAnisotropic(BsdfParams p) {
    return p.anisotropy > 0.0f;
}

// The opaque layer's specular lobe is a mirror: smooth and isotropic (an anisotropic lobe is
// stretched to alpha_t >= strength^2 along its direction, however smooth the material).
INLINE bool specularLobeIsDelta(BsdfParams p) {
    return specularIsDelta(p) && !isAnisotropic(p);
}

// KHR_materials_anisotropy's (alpha_t, alpha_b) of the specular lobe.
INLINE vec2 specularAlphas(BsdfParams p) {
    return anisotropicAlphas(p.roughness * p.roughness, p.anisotropy);
}

// A local direction in the anisotropy frame (+x along anisotropyDirection, +z the same), and back.
INLINE vec3 toAnisotropyFrame(BsdfParams p, vec3 w) {
    vec2 d = p.anisotropyDirection;
    return vec3(d.x * w.x + d.y * w.y, d.x * w.y - d.y * w.x, w.z);
}

INLINE vec3 fromAnisotropyFrame(BsdfParams p, vec3 w) {
    vec2 d = p.anisotropyDirection;
    return vec3(d.x * w.x - d.y * w.y, d.y * w.x + d.x * w.y, w.z);
}

// The opaque layer's GGX lobe without Fresnel (Appendix B's specular_brdf), its sampling pdf and a
// sampled visible normal: isotropic, or anisotropic in the anisotropy frame.
INLINE float specularLobe(BsdfParams p, vec3 wo, vec3 wi) {
    if (!isAnisotropic(p)) return ggxReflection(wo, wi, bsdfAlpha(p));
    return ggxReflectionAnisotropic(toAnisotropyFrame(p, wo), toAnisotropyFrame(p, wi), specularAlphas(p));
}

INLINE float specularLobePdf(BsdfParams p, vec3 wo, vec3 wi) {
    if (!isAnisotropic(p)) return ggxReflectionPdf(wo, wi, bsdfAlpha(p));
    return ggxReflectionPdfAnisotropic(toAnisotropyFrame(p, wo), toAnisotropyFrame(p, wi), specularAlphas(p));
}

INLINE vec3 sampleSpecularNormal(BsdfParams p, vec3 wo, vec2 u) {
    if (!isAnisotropic(p)) return sampleGgxVisibleNormal(wo, bsdfAlpha(p), u);
    return fromAnisotropyFrame(p, sampleGgxVisibleNormalAnisotropic(toAnisotropyFrame(p, wo), specularAlphas(p), u));
}

// The roughness at which the isotropic albedo tables stand in for the specular lobe (energy
// compensation, lobe selection): the roughness itself, or for an anisotropic lobe the one of
// the geometric mean alpha sqrt(alpha_t alpha_b) (an approximation: the tables are isotropic).
INLINE float specularTableRoughness(BsdfParams p) {
    if (!isAnisotropic(p)) return p.roughness;
    vec2 a = specularAlphas(p);
    return sqrt(sqrt(a.x * a.y));
}

INLINE bool clearcoatIsDelta(BsdfParams p) {
    return p.clearcoatRoughness < kDeltaRoughness;
}

INLINE bool hasCoatNormal(BsdfParams p) {
    return (p.flags & kBsdfCoatNormal) != 0u;
}

// A local direction in the coat's own frame (+z = clearcoatNormal), and back. Without a coat
// normal the frames are the same.
INLINE vec3 toCoatFrame(BsdfParams p, vec3 w) {
    if (!hasCoatNormal(p)) return w;
    vec3 t;
    vec3 b;
    orthonormalBasis(p.clearcoatNormal, t, b);
    return toLocal(w, t, b, p.clearcoatNormal);
}

INLINE vec3 fromCoatFrame(BsdfParams p, vec3 w) {
    if (!hasCoatNormal(p)) return w;
    vec3 t;
    vec3 b;
    orthonormalBasis(p.clearcoatNormal, t, b);
    return toWorld(w, t, b, p.clearcoatNormal);
}

// The coat's GGX lobe (without its Fresnel): Appendix B's specular_brdf around the coat normal.
// With a coat normal of its own, the lobe's light is weighted by the coat normal's cosine of wi
// (as the Khronos sample viewer's NdotL of the coat) where every integrator multiplies by the
// shading normal's: the ratio of the two is folded in here.
INLINE float clearcoatReflection(BsdfParams p, vec3 wo, vec3 wi) {
    if (!hasCoatNormal(p)) return ggxReflection(wo, wi, clearcoatAlpha(p));
    vec3 coatWi = toCoatFrame(p, wi);
    return ggxReflection(toCoatFrame(p, wo), coatWi, clearcoatAlpha(p)) * (coatWi.z / wi.z);
}

INLINE float clearcoatReflectionPdf(BsdfParams p, vec3 wo, vec3 wi) {
    return ggxReflectionPdf(toCoatFrame(p, wo), toCoatFrame(p, wi), clearcoatAlpha(p));
}

INLINE bool energyCompensationOn(BsdfParams p) {
    return (p.flags & kBsdfNoEnergyCompensation) == 0u;
}

// KHR_materials_ior's ior = 0: the specular-glossiness compatibility mode, an infinite ior whose
// Fresnel term is 1 in every direction (then scaled by KHR_materials_specular).
INLINE bool iorIsInfinite(BsdfParams p) {
    return p.ior == 0.0f;
}

// KHR_materials_specular's dielectric Fresnel at cos(V, H): specular * (f0 + (1 - f0)(1 - c)^5);
// ior 0: specular * min(specularColor, 1), whatever the direction.
// KHR_materials_iridescence: the film's weight (none without a film: a thickness of 0 turns the
// film off, as the Khronos sample renderer does).
INLINE float iridescenceWeight(BsdfParams p) {
    return p.iridescenceThickness > 0.0f ? p.iridescence : 0.0f;
}

// A Fresnel term `plain` of normal-incidence reflectance f0 with the thin film mixed in by its
// weight (the extension: mix(F, thin-film F, iridescence)), the film over the base seen from air.
INLINE vec3 withThinFilm(BsdfParams p, vec3 plain, vec3 f0, float cosTheta) {
    float k = iridescenceWeight(p);
    if (k <= 0.0f) return plain;
    return mix(plain, thinFilmFresnel(1.0f, p.iridescenceIor, cosTheta, p.iridescenceThickness, f0), k);
}

INLINE vec3 dielectricFresnel(BsdfParams p, float cosTheta) {
    if (iorIsInfinite(p)) {
        vec3 f = min(p.specularColor, vec3(1.0f));
        return p.specular * withThinFilm(p, f, f, cosTheta);
    }
    vec3 f0 = min(vec3(dielectricF0(p.ior)) * p.specularColor, vec3(1.0f));
    return p.specular * withThinFilm(p, fresnelSchlick(f0, cosTheta), f0, cosTheta);
}

// Fresnel of the opaque layer's specular lobe at cos(V, H): the dielectric's and the metal's
// (conductor_fresnel, f0 = baseColor) mixed by metallic; both under the thin film when iridescent.
INLINE vec3 specularFresnel(BsdfParams p, float cosTheta) {
    vec3 metal = withThinFilm(p, fresnelSchlick(p.baseColor, cosTheta), p.baseColor, cosTheta);
    return mix(dielectricFresnel(p, cosTheta), metal, p.metallic);
}

// KHR_materials_clearcoat's Fresnel (ior 1.5: f0 = 0.04) times the coat's weight. vkphoton uses
// cos(V, H) like Appendix B's fresnel_mix, not the extension's non-normative NdotV, so the coated
// BSDF stays reciprocal (photons and importons rely on it).
INLINE float clearcoatFresnel(BsdfParams p, float cosTheta) {
    return p.clearcoat * (0.04f + 0.96f * schlickWeight(cosTheta));
}

// The diffuse lobe's weight: the dielectric's share (1 - metallic) of the opaque layer, less what
// the specular layer reflects, (1 - max(Fd(VdotH))) (fresnel_mix).
INLINE float diffuseWeight(BsdfParams p, float cosTheta) {
    return (1.0f - p.metallic) * (1.0f - maxComponent(dielectricFresnel(p, cosTheta)));
}

INLINE vec3 diffuseAlbedo(BsdfParams p) {
    return (1.0f - p.metallic) * p.baseColor;
}

// KHR_materials_sheen's albedo scaling of the layer under the sheen for one direction:
// 1 - max(sheenColor) E_s(cos theta, sheenRoughness), E_s the directional albedo of the white
// Charlie lobe (bsdf_tables.glsl). evalBsdf takes the smaller of the two directions' scalings
// (min keeps the BSDF reciprocal; the extension's formula uses E_s(N.V) and E_s(N.L) the same way).
INLINE float sheenScaling(BsdfParams p, float cosTheta) {
    if (!kBsdfTablesBound || maxComponent(p.sheenColor) <= 0.0f) return 1.0f;
    float e = bsdfTableLookup(kTableSheenAlbedo, cosTheta, p.sheenRoughness);
    return clamp(1.0f - maxComponent(p.sheenColor) * e, 0.0f, 1.0f);
}

// Kulla-Conty multiple scattering of the GGX specular lobe: f_ms = Fms (1 - E(mu_o))(1 - E(mu_i))
// / (pi (1 - E_avg)) with Fms = Favg^2 E_avg / (1 - Favg (1 - E_avg)) per component, Favg the
// hemispherical average of the Schlick Fresnel (f0 + (1 - f0) / 21, times the specular weight for
// dielectrics). Returns Fms / (pi (1 - E_avg)); zero when compensation is off (material flag
// kBsdfNoEnergyCompensation: render --no-energy-compensation), for mirrors, or when nothing is lost.
INLINE vec3 multipleScatteringColour(BsdfParams p) {
    if (!kBsdfTablesBound || !energyCompensationOn(p) || specularLobeIsDelta(p)) return vec3(0.0f);
    float eAvg = ggxAverageAlbedo(specularTableRoughness(p));
    if (eAvg >= 0.9999f) return vec3(0.0f);
    vec3 f0 = min(vec3(dielectricF0(p.ior)) * p.specularColor, vec3(1.0f));
    vec3 fd = iorIsInfinite(p) ? p.specular * min(p.specularColor, vec3(1.0f))
                               : p.specular * (f0 + (vec3(1.0f) - f0) * (1.0f / 21.0f));
    vec3 fm = p.baseColor + (vec3(1.0f) - p.baseColor) * (1.0f / 21.0f);
    vec3 kd = fd * fd * eAvg / (vec3(1.0f) - fd * (1.0f - eAvg));
    vec3 km = fm * fm * eAvg / (vec3(1.0f) - fm * (1.0f - eAvg));
    return mix(kd, km, p.metallic) * (kInvPi / (1.0f - eAvg));
}

// 1 - E(cos theta, roughness): the share of the light single-scattering GGX loses in one direction.
INLINE float ggxLoss(BsdfParams p, float cosTheta) {
    if (!kBsdfTablesBound) return 0.0f;
    return max(0.0f, 1.0f - bsdfTableLookup(kTableGgxAlbedo, cosTheta, specularTableRoughness(p)));
}

// Probabilities with which sampleBsdf's opaque layer picks its lobes, from the lobes' albedos
// estimated at wo. A lobe that can reflect light keeps at least a tenth of its share of a uniform
// choice, so a poor estimate costs variance, never bias. `diffuse` is the cosine-sampled lobe,
// which also carries the multiple-scattering term.
struct BsdfLobeProbabilities {
    float diffuse;
    float specular;
    float sheen;
    float clearcoat;
};

INLINE BsdfLobeProbabilities bsdfLobeProbabilities(BsdfParams p, float cosO) {
    float coat = clearcoatFresnel(p, cosO);
    float under = (1.0f - coat) * sheenScaling(p, cosO);
    float eDiffuse = under * (luminance(p.baseColor) * diffuseWeight(p, 1.0f) +
                              luminance(multipleScatteringColour(p)) * kPi * ggxLoss(p, cosO));
    float eSpecular = under * luminance(specularFresnel(p, cosO));
    float eSheen = maxComponent(p.sheenColor) > 0.0f
                       ? (1.0f - coat) * luminance(p.sheenColor) * 0.5f
                       : 0.0f;
    float eCoat = coat;
    float lobeCount = (eDiffuse > 0.0f ? 1.0f : 0.0f) + (eSpecular > 0.0f ? 1.0f : 0.0f) +
                      (eSheen > 0.0f ? 1.0f : 0.0f) + (eCoat > 0.0f ? 1.0f : 0.0f);
    BsdfLobeProbabilities q;
    q.diffuse = 0.0f;
    q.specular = 0.0f;
    q.sheen = 0.0f;
    q.clearcoat = 0.0f;
    if (lobeCount == 0.0f) return q;
    float total = eDiffuse + eSpecular + eSheen + eCoat;
    if (eDiffuse > 0.0f) q.diffuse = 0.9f * eDiffuse / total + 0.1f / lobeCount;
    if (eSheen > 0.0f) q.sheen = 0.9f * eSheen / total + 0.1f / lobeCount;
    if (eCoat > 0.0f) q.clearcoat = 0.9f * eCoat / total + 0.1f / lobeCount;
    if (eSpecular > 0.0f) q.specular = max(0.0f, 1.0f - q.diffuse - q.sheen - q.clearcoat);
    return q;
}

// Kept for callers that only need the specular lobe's share.
INLINE float specularSelectProbability(BsdfParams p, float cosO) {
    return bsdfLobeProbabilities(p, cosO).specular;
}

// Below this perceptual roughness a metal's glossy lobe is too narrow for photon density
// estimation: photon paths, camera paths and final gather rays follow it like a mirror.
const float kPhotonGlossyRoughness = 0.2f;

// The surface scatters light diffusely or broadly enough for photon estimates: it stores photons,
// becomes a visible point and ends a final gather ray. Otherwise (smooth glass, mirrors, polished
// metal) paths go on through it and photons that left it are caustic photons.
INLINE bool storesPhotons(BsdfParams p) {
    bool mirrorLike = p.metallic >= 1.0f && (specularLobeIsDelta(p) || specularTableRoughness(p) < kPhotonGlossyRoughness) &&
                      maxComponent(p.sheenColor) <= 0.0f;
    return p.transmission < 1.0f && !mirrorLike;
}

// A Lambertian BSDF: no specular layer (KHR_materials_specular's factor 0), not metallic, no
// sheen, coat, thin film or transmission. Every lobe but the diffuse one is then zero, and
// diffuseWeight is 1, so evalBsdf is baseColor / pi exactly: it returns that without the lobes'
// work (table lookups, GGX), which costs the shared final gathers most (gather_reuse.comp).
INLINE bool bsdfIsLambertian(BsdfParams p) {
    return p.specular == 0.0f && p.metallic == 0.0f && p.clearcoat == 0.0f && p.transmission == 0.0f &&
           maxComponent(p.sheenColor) <= 0.0f && iridescenceWeight(p) <= 0.0f;
}

// The parts of evalBsdf that depend on wo alone: the multiple-scattering colour and
// 1 - E(cos theta_o) (table lookups). A caller that evaluates one BSDF for many wi computes them
// once (evalBsdfWith); evalBsdf computes them at every call.
struct BsdfWoTerms {
    vec3 multipleScattering;  // multipleScatteringColour (zero: no compensation, or a delta lobe)
    float lossWo;             // ggxLoss(p, wo.z) where multipleScattering is not zero
};

INLINE BsdfWoTerms bsdfWoTerms(BsdfParams p, vec3 wo) {
    BsdfWoTerms terms;
    bool none = bsdfIsLambertian(p) || specularLobeIsDelta(p);  // a Lambertian BSDF's is zero too
    terms.multipleScattering = none ? vec3(0.0f) : multipleScatteringColour(p);
    terms.lossWo = maxComponent(terms.multipleScattering) > 0.0f ? ggxLoss(p, wo.z) : 0.0f;
    return terms;
}

// evalBsdf with its wo terms given: the same value.
INLINE vec3 evalBsdfWith(BsdfParams p, BsdfWoTerms terms, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
    if (bsdfIsLambertian(p)) return p.baseColor * kInvPi;
    vec3 h = normalize(wo + wi);
    float cosH = dot(wo, h);
    // glTF base: diffuse + GGX specular (+ multiple scattering).
    vec3 f = p.baseColor * (kInvPi * diffuseWeight(p, cosH));
    if (!specularLobeIsDelta(p)) {
        f = f + specularFresnel(p, cosH) * specularLobe(p, wo, wi);
        vec3 ms = terms.multipleScattering;
        if (maxComponent(ms) > 0.0f) f = f + ms * (terms.lossWo * ggxLoss(p, wi.z));
    }
    // Sheen over the base, clearcoat over both.
    if (maxComponent(p.sheenColor) > 0.0f) {
        f = f * min(sheenScaling(p, wo.z), sheenScaling(p, wi.z)) +
            p.sheenColor * charlieSheen(wo, wi, sheenAlpha(p.sheenRoughness));
    }
    if (p.clearcoat > 0.0f) {
        float fc = clearcoatFresnel(p, cosH);
        f = f * (1.0f - fc);
        if (!clearcoatIsDelta(p)) f = f + vec3(fc * clearcoatReflection(p, wo, wi));
    }
    return f * (1.0f - p.transmission);
}

// evalBsdfWith where the caller knows whether the BSDF is Lambertian (`lambertian` a constant at
// the call, bsdfIsLambertian(p) tested once outside): a loop that evaluates one BSDF for many wi
// gets a copy without the other lobes' code, which lavapipe would run under a lane mask anyway.
INLINE vec3 evalBsdfAs(BsdfParams p, BsdfWoTerms terms, vec3 wo, vec3 wi, const bool lambertian) {
    if (!lambertian) return evalBsdfWith(p, terms, wo, wi);
    return wo.z > 0.0f && wi.z > 0.0f ? p.baseColor * kInvPi : vec3(0.0f);
}

// Non-delta part of the BSDF (f, without the cosine) for local wo, wi; both on the +z side.
INLINE vec3 evalBsdf(BsdfParams p, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);  // before the wo terms' table lookups
    return evalBsdfWith(p, bsdfWoTerms(p, wo), wo, wi);
}

// The diffuse part of the BSDF for light arriving along the normal: what turns precomputed
// irradiance into reflected radiance (Christensen's radiance photons; the glossy part of the
// surface is left out). The multiple-scattering lobe is broad like the diffuse one: it is kept,
// evaluated as evalBsdf does for wi along the normal.
INLINE vec3 diffuseReflectance(BsdfParams p, vec3 wo) {
    if (wo.z <= 0.0f) return vec3(0.0f);
    vec3 h = normalize(wo + vec3(0.0f, 0.0f, 1.0f));
    float cosH = dot(wo, h);
    float layers = (1.0f - clearcoatFresnel(p, cosH)) * min(sheenScaling(p, wo.z), sheenScaling(p, 1.0f));
    vec3 f = p.baseColor * (kInvPi * diffuseWeight(p, cosH));
    if (!specularLobeIsDelta(p)) f = f + multipleScatteringColour(p) * (ggxLoss(p, wo.z) * ggxLoss(p, 1.0f));
    return f * (layers * (1.0f - p.transmission));
}

// Solid-angle pdf with which sampleBsdf produces wi through its non-delta lobes.
INLINE float pdfBsdf(BsdfParams p, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    BsdfLobeProbabilities q = bsdfLobeProbabilities(p, wo.z);
    float pdf = q.diffuse * cosineHemispherePdf(wi.z) + q.sheen * (0.5f * kInvPi);
    if (!specularLobeIsDelta(p)) pdf = pdf + q.specular * specularLobePdf(p, wo, wi);
    if (q.clearcoat > 0.0f && !clearcoatIsDelta(p)) pdf = pdf + q.clearcoat * clearcoatReflectionPdf(p, wo, wi);
    return pdf * (1.0f - p.transmission);
}

// The smooth dielectric layer under KHR_materials_iridescence's film, seen from outside: the
// film's Fresnel (mixed by its weight into the exact one) is a colour, so reflection is chosen with
// the mean of its channels and each branch weighs F / P or (1 - F) / (1 - P) (the refracted branch
// tinted and eta-scaled as sampleDielectric's).
INLINE BsdfSample sampleDielectricFilm(BsdfParams p, vec3 wo, float eta, bool radiance, vec2 u) {
    BsdfSample s;
    s.pdf = 0.0f;
    vec3 f = clamp(mix(vec3(fresnelDielectric(wo.z, eta)),
                       thinFilmFresnel(1.0f, p.iridescenceIor, wo.z, p.iridescenceThickness, vec3(dielectricF0(p.ior))),
                       iridescenceWeight(p)),
                   vec3(0.0f), vec3(1.0f));
    float pReflect = clamp((f.x + f.y + f.z) * (1.0f / 3.0f), 1.0e-4f, 1.0f - 1.0e-4f);
    if (u.x < pReflect) {
        s.wi = vec3(-wo.x, -wo.y, wo.z);
        s.weight = f / pReflect;
        s.lobe = kLobeDelta;
        return s;
    }
    s.lobe = kLobeDelta | kLobeTransmission;
    s.weight = p.baseColor * (vec3(1.0f) - f) / (1.0f - pReflect);
    if (p.thinWalled != 0u) {
        s.wi = -wo;
        return s;
    }
    float cosT = sqrt(max(0.0f, 1.0f - eta * eta * (1.0f - wo.z * wo.z)));
    s.wi = normalize(vec3(-eta * wo.x, -eta * wo.y, -cosT));
    if (radiance) s.weight = s.weight * (eta * eta);
    return s;
}

// Samples the smooth dielectric layer. `entering`: wo is on the outside of the surface.
// `radiance`: scale refracted throughput by eta^2 (camera paths), not for photons (importance).
INLINE BsdfSample sampleDielectric(BsdfParams p, vec3 wo, bool entering, bool radiance, vec2 u) {
    BsdfSample s;
    s.pdf = 0.0f;
    float ior = max(p.ior, 1.0f);
    float eta = entering ? 1.0f / ior : ior;
    if (p.thinWalled != 0u) eta = 1.0f / ior;
    if (entering && iridescenceWeight(p) > 0.0f && !iorIsInfinite(p) && ior > 1.0f)
        return sampleDielectricFilm(p, wo, eta, radiance, u);
    float fr = iorIsInfinite(p) ? 1.0f : fresnelDielectric(wo.z, eta);  // ior 0: an infinite ior reflects all
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

// The ratio n(wo side) / n(other side) of the dielectric layer; thin walls count as entering.
INLINE float dielectricEta(BsdfParams p, bool entering) {
    float ior = max(p.ior, 1.0f);
    return (entering || p.thinWalled != 0u) ? 1.0f / ior : ior;
}

// The dielectric layer is a Dirac: smooth (roughness < kDeltaRoughness), or a solid of ior 1, whose
// microfacets all refract wo to -wo (an invisible interface; Walter's half vector degenerates).
INLINE bool dielectricIsDelta(BsdfParams p) {
    return specularIsDelta(p) || (p.thinWalled == 0u && !iorIsInfinite(p) && p.ior < 1.001f);
}

// f of the rough dielectric layer (tinted, without the 'transmission' weight) for wo.z > 0 and wi on
// either side; what sampleRoughDielectricLayer samples (tests check the two agree).
// KHR_materials_iridescence's film on the dielectric layer, seen from outside (from inside, and for
// an infinite ior, the plain Fresnel), and its parameters for the *RoughDielectricFilm functions.
INLINE bool dielectricHasFilm(BsdfParams p, bool entering) {
    return entering && iridescenceWeight(p) > 0.0f && !iorIsInfinite(p) && p.ior > 1.0f;
}

INLINE vec4 dielectricFilm(BsdfParams p) {
    return vec4(iridescenceWeight(p), p.iridescenceIor, p.iridescenceThickness, dielectricF0(p.ior));
}

INLINE vec3 evalDielectricLayer(BsdfParams p, vec3 wo, vec3 wi, bool entering, bool radiance) {
    if (dielectricIsDelta(p)) return vec3(0.0f);
    if (dielectricHasFilm(p, entering)) {
        vec3 f = evalRoughDielectricFilm(wo, wi, bsdfAlpha(p), dielectricEta(p, entering), p.thinWalled != 0u,
                                         radiance, dielectricFilm(p));
        return wi.z < 0.0f ? p.baseColor * f : f;
    }
    float f = evalRoughDielectric(wo, wi, bsdfAlpha(p), dielectricEta(p, entering), p.thinWalled != 0u,
                                  iorIsInfinite(p), radiance);
    return wi.z < 0.0f ? p.baseColor * f : vec3(f);
}

INLINE float pdfDielectricLayer(BsdfParams p, vec3 wo, vec3 wi, bool entering) {
    if (dielectricIsDelta(p)) return 0.0f;
    if (dielectricHasFilm(p, entering))
        return pdfRoughDielectricFilm(wo, wi, bsdfAlpha(p), dielectricEta(p, entering), p.thinWalled != 0u,
                                      dielectricFilm(p));
    return pdfRoughDielectric(wo, wi, bsdfAlpha(p), dielectricEta(p, entering), p.thinWalled != 0u,
                              iorIsInfinite(p));
}

// Samples the rough dielectric layer (roughness >= kDeltaRoughness). Its samples are distributed by
// pdfDielectricLayer but the lobe is flagged kLobeDelta: evalBsdf does not include the dielectric
// layer, so integrators must take its samples at full weight (as a mirror's), and photon paths
// pass through it like through smooth glass. Rough reflection off the layer is kLobeDelta too,
// transmission adds kLobeTransmission; both carry kLobeLayer, with which the camera-path
// integrators weigh them against next-event estimation (path_vertex.glsl evalVertexDirect).
INLINE BsdfSample sampleRoughDielectricLayer(BsdfParams p, vec3 wo, bool entering, bool radiance, vec3 u) {
    BsdfSample s;
    s.lobe = kLobeNone;
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    float w;
    vec3 wFilm = vec3(0.0f);
    if (dielectricHasFilm(p, entering)) {
        s.wi = sampleRoughDielectricFilm(wo, bsdfAlpha(p), dielectricEta(p, entering), p.thinWalled != 0u, radiance,
                                         dielectricFilm(p), u, wFilm);
        w = max(wFilm.x, max(wFilm.y, wFilm.z));
    } else {
        s.wi = sampleRoughDielectric(wo, bsdfAlpha(p), dielectricEta(p, entering), p.thinWalled != 0u,
                                     iorIsInfinite(p), radiance, u, w);
        wFilm = vec3(w);
    }
    if (s.wi.z == 0.0f || w <= 0.0f) {
        s.wi = vec3(0.0f, 0.0f, 1.0f);
        return s;
    }
    // pdf stays 0 as for every kLobeDelta sample (pdfDielectricLayer has the layer's density).
    if (s.wi.z > 0.0f) {
        s.weight = wFilm;
        s.lobe = kLobeDelta | kLobeLayer;
    } else {
        s.weight = p.baseColor * wFilm;
        s.lobe = kLobeDelta | kLobeTransmission | kLobeLayer;
    }
    return s;
}

// sampleBsdf's choice of lobe and direction: u.x picks the layer (and, rescaled, the opaque lobe),
// u.yz the direction. Delta lobes and the transmission layers come back whole; a sample of an
// opaque non-delta lobe comes back with its direction only (bsdfSampleUnweighted): sampleBsdf
// weighs it by the density of all the opaque lobes, a caller sampling a mixture of the BSDF and
// something else (the guided path tracer) by the mixture's, with one evaluation for both branches.
INLINE BsdfSample sampleBsdfDirection(BsdfParams p, vec3 wo, bool entering, bool radiance, vec3 u) {
    if (u.x < p.transmission) {
        if (dielectricIsDelta(p)) return sampleDielectric(p, wo, entering, radiance, vec2(u.y, u.z));
        return sampleRoughDielectricLayer(p, wo, entering, radiance,
                                          vec3(min(u.x / p.transmission, kOneMinusEpsilon), u.y, u.z));
    }
    BsdfSample s;
    s.lobe = kLobeNone;
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    s.wi = vec3(0.0f, 0.0f, 1.0f);
    if (wo.z <= 0.0f) return s;
    BsdfLobeProbabilities q = bsdfLobeProbabilities(p, wo.z);
    float uLobe = (u.x - p.transmission) / max(1.0f - p.transmission, 1.0e-6f);
    vec3 mirror = vec3(-wo.x, -wo.y, wo.z);
    if (uLobe < q.clearcoat) {
        // Around the coat's normal; a direction below it (or below the shading normal) is no sample.
        vec3 coatWo = toCoatFrame(p, wo);
        if (coatWo.z <= 0.0f) return s;
        if (clearcoatIsDelta(p)) {
            s.wi = fromCoatFrame(p, vec3(-coatWo.x, -coatWo.y, coatWo.z));
            if (s.wi.z <= 0.0f) return s;
            s.weight = vec3(clearcoatFresnel(p, coatWo.z) / q.clearcoat);
            s.lobe = kLobeDelta;
            return s;
        }
        vec3 coatWi = reflect(-coatWo, sampleGgxVisibleNormal(coatWo, clearcoatAlpha(p), vec2(u.y, u.z)));
        if (coatWi.z <= 0.0f) return s;
        s.wi = fromCoatFrame(p, coatWi);
        s.lobe = kLobeGlossy;
    } else if (uLobe < q.clearcoat + q.specular) {
        if (specularLobeIsDelta(p)) {
            // The mirror's light passes the coat and the sheen twice (along wo = wi's mirror).
            float layers = (1.0f - clearcoatFresnel(p, wo.z)) * sheenScaling(p, wo.z);
            s.wi = mirror;
            s.weight = specularFresnel(p, wo.z) * (layers / q.specular);
            s.lobe = kLobeDelta;
            return s;
        }
        s.wi = reflect(-wo, sampleSpecularNormal(p, wo, vec2(u.y, u.z)));
        s.lobe = kLobeGlossy;
    } else if (uLobe < q.clearcoat + q.specular + q.sheen) {
        // Uniform hemisphere: the sheen lobe is broad and strongest towards grazing.
        float z = u.y;
        float r = sqrt(max(0.0f, 1.0f - z * z));
        float phi = kTwoPi * u.z;
        s.wi = vec3(r * cos(phi), r * sin(phi), z);
        s.lobe = kLobeDiffuse;
    } else if (q.diffuse > 0.0f) {
        s.wi = sampleCosineHemisphere(vec2(u.y, u.z));
        s.lobe = kLobeDiffuse;
    } else {
        return s;
    }
    if (s.wi.z <= 0.0f) s.lobe = kLobeNone;
    return s;
}

// A sample of an opaque non-delta lobe, whose pdf and weight are still to be set.
INLINE bool bsdfSampleUnweighted(BsdfSample s) {
    return s.lobe != kLobeNone && (s.lobe & (kLobeDelta | kLobeTransmission | kLobeLayer)) == 0u;
}

// Samples the whole BSDF: u.x picks the layer (and, rescaled, the opaque lobe), u.yz the direction.
INLINE BsdfSample sampleBsdf(BsdfParams p, vec3 wo, bool entering, bool radiance, vec3 u) {
    BsdfSample s = sampleBsdfDirection(p, wo, entering, radiance, u);
    if (!bsdfSampleUnweighted(s)) return s;
    // Every non-delta lobe could have produced wi: weight by the full mixture pdf (delta lobes
    // are excluded, they have probability zero of producing this direction).
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
