// sampleBsdf on the GPU for the chi-square test of tests/shared/bsdf_test.cpp: one material and one
// outgoing direction (BsdfSamplingCase), one sample per random triple; out = (wi, 1) or (0, 0) when
// no lobe was sampled. The host bins the directions against pdfBsdf.
#version 460
#extension GL_GOOGLE_include_directive : require

#define VKP_BSDF_TABLES_BINDING 3u  // kBsdfSamplingTablesBinding (test_kernels.glsl)
#include "test_kernels.glsl"

layout(local_size_x = kTestGroupSize) in;
layout(std430, set = 0, binding = kBsdfSamplingCaseBinding) readonly buffer Case { BsdfSamplingCase testCase; };
layout(std430, set = 0, binding = kBsdfSamplingRandomBinding) readonly buffer Random { vec4 randoms[]; };
layout(std430, set = 0, binding = kBsdfSamplingOutputBinding) writeonly buffer Outputs { vec4 outputs[]; };
layout(push_constant) uniform Push { uint count; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count) return;
    vec4 u = randoms[i];
    BsdfSample s = sampleBsdf(testCase.bsdf, testCase.wo.xyz, true, true, u.xyz);
    outputs[i] = s.lobe == kLobeNone ? vec4(0.0f) : vec4(s.wi, 1.0f);
}
