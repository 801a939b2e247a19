// The toy integrator of tests/render/integrator_seam_render_test.cpp (its interface: ConstantFilmKernel in
// test_kernels.glsl): adds `sampleCount` samples of a constant radiance to every film pixel.
#version 460
#extension GL_GOOGLE_include_directive : require

#define VKP_NO_BSDF_TABLES  // evaluates no BSDF (test_kernels.glsl includes it for its types)
#include "test_kernels.glsl"

layout(local_size_x = kTestGroupSize) in;
layout(std430, set = 0, binding = kConstantFilmBinding) buffer Film { vec4 film[]; };
layout(push_constant) uniform Push { ConstantFilmParams params; };

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.pixels) return;
    film[pixel] += vec4(params.radiance.rgb * float(params.sampleCount), float(params.sampleCount));
}
