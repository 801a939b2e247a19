// The kernel of PhotonMapSegmentsTest.KernelsOfOneSegmentArraysIndexItDirectly: reads and writes a
// segmented array through UINT_AT and says which form of shaders/common/segmented_arrays.glsl ran.
#version 460
#extension GL_GOOGLE_include_directive : require

#define VKP_NO_BSDF_TABLES  // evaluates no BSDF (test_kernels.glsl includes it for its types)
#include "test_kernels.glsl"
#include "common/segmented_arrays.glsl"

layout(local_size_x = kTestGroupSize) in;
SEGMENTED_ARRAY(kSegmentedTestArrayBinding, Array, array);
layout(std430, set = 0, binding = kSegmentedTestOutputBinding) writeonly buffer Outputs { uint outputs[]; };
layout(push_constant) uniform Push { SegmentedTestParams params; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i == 0u) outputs[0] = kSingleSegment ? 1u : 0u;
    if (i < params.count) {
        uint value = UINT_AT(array, i);
        outputs[1u + i] = value;
        UINT_AT(array, i) = value + 1u;
    }
}
