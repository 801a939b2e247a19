// Gather throughput: one query per invocation at the position and normal of every stride-th
// photon of a map (queries where the scene's surfaces are): mode 0 a fixed-radius sum, mode 1 a
// k-nearest estimate, mode 2 one nearest neighbour (the radiance-photon lookup).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/sampling.glsl"
#define VKP_NO_BSDF_TABLES  // gathers photon power only
#include "shared/bsdf.glsl"
#include "bench_kernels.glsl"
#define PHOTON_GRID_BINDING kGatherBenchGridBinding
#include "photon/photon_gather.glsl"

layout(local_size_x = kBenchGroupSize) in;

layout(std430, set = 0, binding = kGatherBenchResultBinding) writeonly buffer Results { float results[]; };

layout(push_constant) uniform Push { GatherBenchParams push; };

void main() {
    uint q = gl_GlobalInvocationID.x;
    if (q >= push.queries) return;
    GpuPhoton p = gridPhoton(q * push.stride);
    vec3 n = decodeOctahedral(p.normal);
    vec3 t;
    vec3 b;
    orthonormalBasis(n, t, b);
    BsdfParams bsdf = makeBsdfParams(vec3(0.8f), 0.0f, 1.0f);
    vec3 wo = vec3(0.0f, 0.0f, 1.0f);
    float value;
    if (push.mode == 0u) {
        FixedRadiusGather g = gatherFixedRadius(push.grid, p.position, push.radius, 1.1f, 0u, 0u, bsdf, wo, t, b, n);
        value = g.weightedPower.x + float(g.count);
    } else if (push.mode == 1u) {
        value = radianceNearest(push.grid, p.position, push.k, push.radius, 0u, 0u, bsdf, wo, t, b, n).x;
    } else {
        float radius2;
        value = float(gatherNearest(push.grid, p.position, n, 1u, push.radius, 0u, 0u, radius2)) + radius2;
    }
    results[q] = value;
}
