// Thin-film interference for KHR_materials_iridescence: the Fresnel reflectance of a dielectric
// film (index filmIor, thickness in nanometres) between the outside (outsideIor) and the base
// (whose index comes from its normal-incidence reflectance F0), by Belcour & Barla 2017, "A
// Practical Extension to Microfacet Theory for the Modeling of Varying Iridescence", in the form
// the extension specifies: Schlick's approximation at both interfaces, the Airy sum to its first
// two orders, and the spectral integral against the CIE XYZ matching functions evaluated in
// Fourier space with Gaussian fits, converted to linear sRGB (Rec. 709 primaries).
#ifndef VKP_BSDF_IRIDESCENCE_GLSL
#define VKP_BSDF_IRIDESCENCE_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "cie.glsl"
SHARED_BEGIN

// The spectral sensitivity of a path difference `opd` (nm) with phase `shift` per XYZ channel:
// the Fourier transform of the colour matching functions (Belcour & Barla's Gaussian fit), in
// linear sRGB.
INLINE vec3 thinFilmSensitivity(float opd, vec3 shift) {
    float phase = kTwoPi * opd * 1.0e-9f;
    vec3 val = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    vec3 pos = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    vec3 var = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    vec3 xyz = val * sqrt(kTwoPi * var) * cos(pos * phase + shift) * exp(-(phase * phase) * var);
    xyz.x = xyz.x + 9.7470e-14f * sqrt(kTwoPi * 4.5282e+09f) * cos(2.2399e+06f * phase + shift.x) *
                        exp(-4.5282e+09f * phase * phase);
    return xyzToLinearSrgb(xyz / 1.0685e-7f);
}

INLINE float schlickF0(float ior, float outsideIor) {
    float r = (ior - outsideIor) / (ior + outsideIor);
    return r * r;
}

// Reflectance of the film over a base of normal-incidence reflectance baseF0, for the cosine
// cosTheta1 of the angle of incidence outside. The film's index goes to the outside's as its
// thickness goes to 0 (over 0.03 nm), so a vanishing film is no interface.
INLINE vec3 thinFilmFresnel(float outsideIor, float filmIor, float cosTheta1, float thickness, vec3 baseF0) {
    float ior2 = mix(outsideIor, filmIor, smoothstep(0.0f, 0.03f, thickness));
    float sinTheta2Sq = (outsideIor / ior2) * (outsideIor / ior2) * (1.0f - cosTheta1 * cosTheta1);
    float cosTheta2Sq = 1.0f - sinTheta2Sq;
    if (cosTheta2Sq < 0.0f) return vec3(1.0f);  // total internal reflection at the film
    float cosTheta2 = sqrt(cosTheta2Sq);
    // First interface (outside to film), Schlick.
    float r0 = schlickF0(ior2, outsideIor);
    float c1 = clamp(1.0f - cosTheta1, 0.0f, 1.0f);
    float r12 = r0 + (1.0f - r0) * (c1 * c1 * c1 * c1 * c1);
    float t121 = 1.0f - r12;
    float phi12 = ior2 < outsideIor ? kPi : 0.0f;
    float phi21 = kPi - phi12;
    // Second interface (film to base): the base's index from its F0 (against air).
    vec3 sqrtF0 = sqrt(clamp(baseF0, vec3(0.0f), vec3(0.9999f)));
    vec3 baseIor = (vec3(1.0f) + sqrtF0) / (vec3(1.0f) - sqrtF0);
    vec3 r1 = (baseIor - vec3(ior2)) / (baseIor + vec3(ior2));
    r1 = r1 * r1;
    float c2 = clamp(1.0f - cosTheta2, 0.0f, 1.0f);
    vec3 r23 = r1 + (vec3(1.0f) - r1) * (c2 * c2 * c2 * c2 * c2);
    vec3 phi23 = vec3(baseIor.x < ior2 ? kPi : 0.0f, baseIor.y < ior2 ? kPi : 0.0f, baseIor.z < ior2 ? kPi : 0.0f);
    // Optical path difference and phase of one round trip in the film.
    float opd = 2.0f * ior2 * thickness * cosTheta2;
    vec3 phi = vec3(phi21) + phi23;
    vec3 r123 = clamp(r12 * r23, vec3(1.0e-5f), vec3(0.9999f));
    vec3 sqrtR123 = sqrt(r123);
    vec3 rs = (t121 * t121) * r23 / (vec3(1.0f) - r123);
    // The Airy sum: the mean term, then the first two orders of interference.
    vec3 c0 = vec3(r12) + rs;
    vec3 result = c0;
    vec3 cm = rs - vec3(t121);
    cm = cm * sqrtR123;
    result = result + cm * (2.0f * thinFilmSensitivity(opd, phi));
    cm = cm * sqrtR123;
    result = result + cm * (2.0f * thinFilmSensitivity(2.0f * opd, 2.0f * phi));
    return max(result, vec3(0.0f));  // out-of-gamut colours clamped, as the extension does
}

SHARED_END
#endif
