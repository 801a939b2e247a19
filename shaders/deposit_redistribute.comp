// Density control's redistribution (Suykens & Willems 2000, §3.1), after each round's decisions:
// adds the power that rejected photons handed to each photon of the map's grid to that photon in
// the map (the grid's sorted slots lead back to it) and clears the sum for the next round.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/deposit.glsl"
#include "shared/importance.glsl"
#include "shared/photon.glsl"

layout(local_size_x = kDepositGroupSize) in;

layout(std430, set = 0, binding = kRedistributeMapBinding) buffer Map { GpuPhoton map[]; };
layout(std430, set = 0, binding = kRedistributeSortedSlotBinding) readonly buffer SortedSlots { uint sortedSlots[]; };
layout(std430, set = 0, binding = kRedistributeRedistributedBinding) buffer Redistributed { uint redistributed[]; };

layout(push_constant) uniform Push { RedistributeParams params; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.gridPhotons) return;
    uvec3 added = uvec3(redistributed[3u * i], redistributed[3u * i + 1u], redistributed[3u * i + 2u]);
    if (added == uvec3(0u)) return;
    uint slot = sortedSlots[i];
    vec3 power = photonRelativePower(map[slot]) + vec3(added) / kRedistributedFixedPoint;
    map[slot] = withRelativePower(map[slot], min(power, vec3(kMaxHalfFloat)));
    redistributed[3u * i] = 0u;
    redistributed[3u * i + 1u] = 0u;
    redistributed[3u * i + 2u] = 0u;
}
