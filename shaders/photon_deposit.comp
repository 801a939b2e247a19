// Deposition: decides for every traced photon slot whether the map keeps the photon (Keller &
// Wald's probabilistic deposition, or Suykens & Willems' density control with Russian-roulette
// weighting), from the importance looked up by importance_lookup.comp. A kept photon's power is
// divided by its acceptance probability, so the map's flux stays an unbiased estimate of the
// deposited flux; a dropped photon's slot is cleared. The random decision depends only on the
// path's Halton index and the deposit's number along the path, so the maps of one run agree.
#version 460
#extension GL_GOOGLE_include_directive : require

#define PHOTON_GRID_BINDING 8
#include "scene_access.glsl"
#include "photon_gather.glsl"
#include "shared/hash.glsl"
#include "shared/importance.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 10) buffer Slots { GpuPhoton slots[]; };
layout(std430, set = 0, binding = 11) readonly buffer Importance { vec2 importance[]; };

layout(push_constant) uniform Push { PhotonDepositParams params; };

const uint kDepositStream = 0x44455053u;  // "DEPS"

// Photons of the map within densityRadius of x over the disk holding the densityK nearest.
float currentDensity(vec3 x, vec3 n) {
    if (params.round == 0u) return 0.0f;  // nothing stored yet: the grid is not built
    float radius2;
    uint found = gatherNearest(params.map, x, n, params.densityK, params.densityRadius, 0u, 0u, radius2);
    return float(found) / (kPi * radius2);
}

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount) return;
    GpuPhoton p = slots[slot];
    if (!photonSelected(photonFlags(p), params.requiredFlags, params.rejectedFlags)) return;
    vec2 sensed = importance[slot];
    float accept;
    if (params.mode == kDepositDensity) {
        float required = max(params.densityAccuracy * sensed.y, params.minDensity);
        accept = densityAcceptance(currentDensity(p.position, decodeOctahedral(p.normal)), required);
        // Russian roulette against an over-dense region: the weight 1 / p stays below
        // 1 / densityFloor, so the map's photons keep nearly equal powers (Suykens & Willems saw
        // the variance grow with the weights).
        if (required > 0.0f) accept = max(accept, params.densityFloor);
    } else {
        accept = importanceAcceptance(sensed.x, params.importanceScale);
    }
    accept = flooredAcceptance(accept, params.epsilon, params.cutoff != 0u);
    uint path = params.firstPath + slot / params.maxDeposits;
    uint deposit = slot % params.maxDeposits;
    float xi = uintToUnitFloat(hashCombine(hashCombine(hashCombine(params.seed, kDepositStream), path), deposit));
    if (xi < accept) {
        vec3 power = min(photonRelativePower(p) / accept, vec3(kMaxHalfFloat));
        slots[slot] = withRelativePower(p, power);
    } else {
        GpuPhoton empty;
        empty.position = vec3(0.0f);
        empty.powerRG = 0u;
        empty.powerBFlags = 0u;
        empty.direction = 0u;
        empty.normal = 0u;
        empty.lightIndex = 0u;
        slots[slot] = empty;
    }
}
