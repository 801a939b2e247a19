// The kernel of tests/vk/kernel_interface_test.cpp: its interface (InterfaceTestKernel,
// test_kernels.glsl) is checked against this shader's SPIR-V when the kernel is created, and the
// test also tells it interfaces that disagree (push constants, bindings, workgroup size).
#version 460
#extension GL_GOOGLE_include_directive : require

#define VKP_NO_BSDF_TABLES  // evaluates no BSDF (test_kernels.glsl includes it for its types)
#include "test_kernels.glsl"

layout(local_size_x = kTestGroupSize) in;
layout(std430, set = 0, binding = kInterfaceTestInputBinding) readonly buffer Inputs { uint inputs[]; };
layout(std430, set = 0, binding = kInterfaceTestOutputBinding) writeonly buffer Outputs { uint outputs[]; };
layout(push_constant) uniform Push { InterfaceTestParams params; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < params.count) outputs[i] = inputs[i] * params.scale + params.offset;
}
