// CIE 1931 colorimetry shared by the spectral parts of the BSDF (thin films, dispersion).
#ifndef VKP_CIE_GLSL
#define VKP_CIE_GLSL
#include "compat.glsl"
SHARED_BEGIN

// XYZ (CIE 1931) to linear sRGB (Rec. 709 primaries, D65 white).
INLINE vec3 xyzToLinearSrgb(vec3 c) {
    return vec3(3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z,
                -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z,
                0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z);
}

INLINE float cieLobe(float lambda, float mu, float below, float above) {
    float t = (lambda - mu) / (lambda < mu ? below : above);
    return exp(-0.5f * t * t);
}

// The CIE 1931 2-degree matching functions x-bar, y-bar, z-bar at lambda (nm): the multi-lobe fit of
// Wyman, Sloan & Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions", JCGT 2(2).
INLINE vec3 cieMatching(float lambda) {
    return vec3(1.056f * cieLobe(lambda, 599.8f, 37.9f, 31.0f) + 0.362f * cieLobe(lambda, 442.0f, 16.0f, 26.7f) -
                    0.065f * cieLobe(lambda, 501.1f, 20.4f, 26.2f),
                0.821f * cieLobe(lambda, 568.8f, 46.9f, 40.5f) + 0.286f * cieLobe(lambda, 530.9f, 16.3f, 31.1f),
                1.217f * cieLobe(lambda, 437.0f, 11.8f, 36.0f) + 0.681f * cieLobe(lambda, 459.0f, 26.0f, 13.8f));
}

SHARED_END
#endif
