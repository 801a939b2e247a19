// Test kernel for shaders/photon/photon_gather.glsl: runs a fixed-radius gather and a k-nearest gather
// for each query; tests/photon/photon_grid_test.cpp compares both with brute force on the host.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/sampling.glsl"
#define VKP_NO_BSDF_TABLES  // no albedo tables: the test sets kBsdfNoEnergyCompensation on both sides
#include "shared/bsdf.glsl"
#include "test_kernels.glsl"
#define PHOTON_GRID_BINDING kGatherTestGridBinding
#include "photon/photon_gather.glsl"

layout(local_size_x = kTestGroupSize) in;

struct GatherQuery {
    vec3 position;
    float radius;
    vec3 normal;
    uint k;
};

layout(std430, set = 0, binding = kGatherTestQueryBinding) readonly buffer Queries { GatherQuery queries[]; };
layout(std430, set = 0, binding = kGatherTestFixedBinding) writeonly buffer FixedResults { vec4 fixedResults[]; };   // sum, count
layout(std430, set = 0, binding = kGatherTestNearestBinding) writeonly buffer NearestResults { uint nearestResults[]; };  // see below

layout(std430, set = 0, binding = kGatherTestBsdfBinding) readonly buffer Bsdf { BsdfParams bsdf; };
layout(push_constant) uniform Push { GatherTestParams push; };

void main() {
    uint q = gl_GlobalInvocationID.x;
    if (q >= push.count) return;
    GatherQuery query = queries[q];
    vec3 n = query.normal;
    vec3 t;
    vec3 b;
    orthonormalBasis(n, t, b);
    vec3 wo = normalize(vec3(0.3f, -0.2f, 1.0f));
    FixedRadiusGather fixedGather = gatherFixedRadius(push.grid, query.position, query.radius, push.coneK,
                                                      push.requiredFlags, push.rejectedFlags, bsdf, wo, t, b, n);
    fixedResults[q] = vec4(fixedGather.weightedPower, float(fixedGather.count));

    // Per query: found, radius2 (float bits), then the photons' lightIndex fields (their ids).
    float radius2;
    uint found = gatherNearest(push.grid, query.position, n, query.k, query.radius, push.requiredFlags,
                               push.rejectedFlags, radius2);
    uint base = q * (kMaxGatherK + 2u);
    nearestResults[base] = found;
    nearestResults[base + 1u] = floatBitsToUint(radius2);
    for (uint j = 0u; j < found; ++j) nearestResults[base + 2u + j] = gridPhoton(heapIndex[j]).lightIndex;
}
