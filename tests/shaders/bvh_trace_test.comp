// GPU side of the BVH test: traces each ray with traceClosest and traceAny
// (shaders/shared/bvh_traverse.glsl); the host compares with closestHit/anyHit of host/bvh/bvh.h
// (the same header compiled as C++), which tests/bvh/bvh_test.cpp checks against brute force.
//
// Host layouts (std430, all 4-byte scalars):
//   binding 0  TestRay { vec4 origin (xyz, w = tMax); vec4 direction (xyz, w unused) }  32 B
//   binding 1  GpuBvhNode[]   (Bvh::nodes)
//   binding 2  GpuTriangle[]  (gpuTriangles(), BVH order)
//   binding 3  TestHit { float t; uint tri; float b1; float b2; uint anyHit; }         20 B
//              miss: t = tMax, tri = 0xffffffff (kBvhNoTriangle), b1 = b2 = 0; tri is the hit id
//   binding 4  GpuInstanceHeader, GpuInstance[]  (instanceCount 0: the single tree at node 0)
//   push constant: uint rayCount
//   set 1: the termination counters (a ray whose traversal was cut short counts as a sample)
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/gpu_types.glsl"
#include "shared/constants.glsl"
#define VKP_NO_BSDF_TABLES  // evaluates no BSDF (test_kernels.glsl includes it for its types)
#include "test_kernels.glsl"

layout(local_size_x = kTestGroupSize) in;

struct TestRay {
    vec4 origin;
    vec4 direction;
};

struct TestHit {
    float t;
    uint tri;
    float b1;
    float b2;
    uint anyHit;
};

layout(std430, set = 0, binding = kBvhTestRayBinding) readonly buffer Rays { TestRay rays[]; };
layout(std430, set = 0, binding = kBvhTestNodeBinding) readonly buffer BvhNodes { GpuBvhNode bvhNodes[]; };
layout(std430, set = 0, binding = kBvhTestTriangleBinding) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, set = 0, binding = kBvhTestHitBinding) writeonly buffer Hits { TestHit hits[]; };
layout(std430, set = 0, binding = kBvhTestInstanceBinding) readonly buffer Instances {
    GpuInstanceHeader instanceHeader;
    GpuInstance instances[];
};
layout(push_constant) uniform Push { uint rayCount; } push;

#include "render/scene_geometry.glsl"  // texel-buffer reads when specialized for them (bvhTexels)
#include "shared/bvh_traverse.glsl"
#include "common/termination_counters.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.rayCount) return;
    TestRay ray = rays[i];
    vec3 org = ray.origin.xyz;
    vec3 dir = ray.direction.xyz;
    float tMax = ray.origin.w;
    TestHit h;
    traceClosest(org, dir, tMax, false, h.t, h.tri, h.b1, h.b2);
    h.anyHit = traceAny(org, dir, tMax) ? 1u : 0u;
    hits[i] = h;
    countTerminations(kTerminationSamples);  // a ray cut short counts as one sample
}
