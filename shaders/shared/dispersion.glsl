// KHR_materials_dispersion: a dielectric's index of refraction by wavelength, and the spectral
// sampling that follows it (docs/materials.md, "Dispersion"). A path is white (RGB) until it meets
// a dispersive transmissive surface; there it takes one wavelength, drawn uniformly over
// [kWavelengthMin, kWavelengthMax], its RGB throughput is multiplied by spectralWeight(lambda), and
// every later dispersive refraction on the path uses that wavelength's index.
#ifndef VKP_DISPERSION_GLSL
#define VKP_DISPERSION_GLSL
#include "compat.glsl"
#include "cie.glsl"
SHARED_BEGIN

const float kWavelengthMin = 380.0f;  // nm
const float kWavelengthMax = 780.0f;

// The extension's Cauchy form through the index `ior` at 587.6 nm (the Fraunhofer d line) with
// Abbe number V = 20 / dispersion: ior(lambda) = ior + (ior - 1) / V (523655 / lambda^2 - 1.5168),
// lambda in nm. dispersion 0 (or ior 0, the infinite index) leaves the index alone.
INLINE float dispersiveIor(float ior, float dispersion, float lambda) {
    if (!(dispersion > 0.0f) || ior == 0.0f) return ior;
    return ior + (ior - 1.0f) * (dispersion / 20.0f) * (523655.0f / (lambda * lambda) - 1.5168f);
}

// The RGB basis c(lambda): the linear-sRGB matching functions (XYZ to Rec. 709 of the CIE curves),
// negative lobes clamped to 0, each channel divided by its integral over [380, 780] nm (176.177,
// 115.386, 109.318 nm; tests/shared/dispersion_test.cpp checks them), so that every channel of the
// basis integrates to 1: white light split into wavelengths and summed again is white, and each
// channel keeps its energy.
INLINE vec3 spectralBasis(float lambda) {
    vec3 rgb = xyzToLinearSrgb(cieMatching(lambda));
    return max(rgb, vec3(0.0f)) / vec3(176.17732f, 115.38557f, 109.31846f);
}

// The wavelength for a uniform u in [0, 1), and the weight c(lambda) / pdf(lambda) the throughput
// takes with it (the pdf is uniform, 1 / 400 nm): its mean over u is (1, 1, 1).
INLINE float sampleWavelength(float u) {
    return kWavelengthMin + (kWavelengthMax - kWavelengthMin) * u;
}

INLINE vec3 spectralWeight(float lambda) {
    return spectralBasis(lambda) * (kWavelengthMax - kWavelengthMin);
}

SHARED_END
#endif
