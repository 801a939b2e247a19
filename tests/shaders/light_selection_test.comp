// Light sampler harness kernel: evaluateLightHarness (light_selection_harness.glsl) for `count`
// inputs over the scene's light-selection data; tests/lights/light_selection_test.cpp runs the same code
// compiled as C++ and compares.
#version 460
#extension GL_GOOGLE_include_directive : require

#define VKP_NO_BSDF_TABLES
#include "shared/gpu_types.glsl"
#include "test_kernels.glsl"

layout(std430, set = 0, binding = kLightTestSelectionBinding) readonly buffer LightCdf { float lightCdf[]; };
layout(std430, set = 0, binding = kLightTestLightBinding) readonly buffer Lights { GpuLight lights[]; };

#include "light_selection_harness.glsl"

layout(local_size_x = kTestGroupSize) in;
layout(std430, set = 0, binding = kLightTestInputBinding) readonly buffer Inputs { LightHarnessInput inputs[]; };
layout(std430, set = 0, binding = kLightTestOutputBinding) writeonly buffer Outputs { LightHarnessOutput outputs[]; };
layout(push_constant) uniform Push { LightTestParams params; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) return;
    outputs[i] = evaluateLightHarness(params.lightCount, inputs[i]);
}
