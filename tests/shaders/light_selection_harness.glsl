// The light sampler's shared functions as the GPU/C++ harness runs them
// (tests/shaders/light_selection_test.comp against the C++ build, tests/lights/light_selection_test.cpp):
// per input, one next-event light choice at (p, n) with its pdf, selectLightPdf of the chosen light
// and of another one, and one solid-angle sample of a triangle with its pdf. The GLSL includer
// declares lightCdf[] and lights[] first (shared/light_selection.glsl).
#ifndef VKP_LIGHT_SELECTION_HARNESS_GLSL
#define VKP_LIGHT_SELECTION_HARNESS_GLSL
#include "shared/compat.glsl"
#include "shared/light_selection.glsl"
#include "shared/spherical_triangle.glsl"
SHARED_BEGIN

struct LightHarnessInput {
    vec4 p;    // xyz: shading point
    vec4 n;    // xyz: shading normal
    vec4 v0;   // xyz: a triangle for sampleSphericalTriangle
    vec4 v1;
    vec4 v2;
    vec4 u;    // x: light choice, y: the other light, zw: the triangle sample
};
STATIC_ASSERT_SIZE(LightHarnessInput, 96)

struct LightHarnessOutput {
    vec4 selection;  // chosen index (bits), its pdf, selectLightPdf(chosen), selectLightPdf(other)
    vec4 triangle;   // barycentrics b1, b2, ok (1 / 0), triangleLightPdf at the centroid
};
STATIC_ASSERT_SIZE(LightHarnessOutput, 32)

INLINE LightHarnessOutput evaluateLightHarness(LIGHT_SELECTION_PARAM uint lightCount, LightHarnessInput in_) {
    vec3 p = vec3(in_.p.x, in_.p.y, in_.p.z);
    vec3 n = vec3(in_.n.x, in_.n.y, in_.n.z);
    LightHarnessOutput r;
    LightChoice c = selectLight(LIGHT_SELECTION_ARG lightCount, p, n, in_.u.x);
    uint other = min(uint(in_.u.y * float(lightCount)), lightCount - 1u);
    r.selection = vec4(uintBitsToFloat(c.index), c.pdf, selectLightPdf(LIGHT_SELECTION_ARG lightCount, p, n, c.index),
                       selectLightPdf(LIGHT_SELECTION_ARG lightCount, p, n, other));
    vec3 v0 = vec3(in_.v0.x, in_.v0.y, in_.v0.z);
    vec3 v1 = vec3(in_.v1.x, in_.v1.y, in_.v1.z);
    vec3 v2 = vec3(in_.v2.x, in_.v2.y, in_.v2.z);
    bool ok;
    vec2 b = sampleSphericalTriangle(v0, v1, v2, p, vec2(in_.u.z, in_.u.w), ok);
    // The pdf at the centroid (at the sampled point it would take the warp's differences along).
    vec3 middle = (v0 + v1 + v2) / 3.0f;
    r.triangle = vec4(b.x, b.y, ok ? 1.0f : 0.0f, triangleLightPdf(v0, v1, v2, p, middle, true));
    return r;
}

SHARED_END
#endif
