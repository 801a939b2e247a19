// Deposition: decides for every traced photon slot whether the map keeps the photon (Keller &
// Wald's probabilistic deposition, or Suykens & Willems' density control), from the importance
// looked up by importance_lookup.comp. A kept photon's power is divided by its acceptance
// probability, so the map's flux stays an unbiased estimate of the deposited flux — or, with
// density control's redistribution, a rejected photon's power goes to its stored neighbours
// (deposit_redistribute.comp adds it to them). A dropped photon's slot is cleared. The random decision depends only on the
// path's Halton index and the deposit's number along the path, so the maps of one run agree.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/deposit.glsl"
#define PHOTON_GRID_BINDING kPhotonDepositGridBinding
#include "render/scene_access.glsl"
#include "photon/photon_gather.glsl"
#include "shared/hash.glsl"
#include "shared/importance.glsl"

layout(local_size_x = kDepositGroupSize) in;

layout(std430, set = 0, binding = kPhotonDepositSlotBinding) buffer Slots { GpuPhoton slots[]; };
layout(std430, set = 0, binding = kPhotonDepositImportanceBinding) readonly buffer Importance { vec2 importance[]; };
// Per photon of the map's grid, rgb: power redistributed to it (density control, fixed point),
// words 3 i .. 3 i + 2 of a segmented array (segmented.glsl).
SEGMENTED_ARRAY(kPhotonDepositRedistributedBinding, Redistributed, redistributedTable);

layout(push_constant) uniform Push { PhotonDepositParams params; };

const uint kDepositStream = 0x44455053u;  // "DEPS"

GpuPhoton emptyPhoton() {
    GpuPhoton empty;
    empty.position = vec3(0.0f);
    empty.powerRG = 0u;
    empty.powerBFlags = 0u;
    empty.direction = 0u;
    empty.normal = 0u;
    empty.lightIndex = 0u;
    return empty;
}

// Photons of the map within densityRadius of x over the disk holding the densityK nearest;
// `found` of them, their grid indices in heapIndex.
float currentDensity(vec3 x, vec3 n, out uint found) {
    found = 0u;
    if (params.round == 0u) return 0.0f;  // nothing stored yet: the grid is not built
    float radius2;
    found = gatherNearest(params.map, x, n, params.densityK, params.densityRadius, 0u, 0u, radius2);
    return float(found) / (kPi * radius2);
}

// Suykens & Willems: a rejected photon's power goes in equal shares to the stored photons that
// its current-density estimate found (all on surfaces facing its way: the gather's normal test).
void redistribute(vec3 power, uint found) {
    uvec3 share = uvec3(power / float(found) * kRedistributedFixedPoint + 0.5f);
    for (uint j = 0u; j < found; ++j) {
        uint i = heapIndex[j];
        atomicAdd(UINT_AT(redistributedTable, 3u * i), share.x);
        atomicAdd(UINT_AT(redistributedTable, 3u * i + 1u), share.y);
        atomicAdd(UINT_AT(redistributedTable, 3u * i + 2u), share.z);
    }
}

void deposit() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount) return;
    GpuPhoton p = slots[slot];
    if (!photonSelected(photonFlags(p), params.requiredFlags, params.rejectedFlags)) return;
    vec2 sensed = importance[slot];
    uint path = params.firstPath + slot / params.maxDeposits;
    uint deposit = slot % params.maxDeposits;
    float xi = uintToUnitFloat(hashCombine(hashCombine(hashCombine(params.seed, kDepositStream), path), deposit));
    float accept;
    if (params.mode == kDepositDensity) {
        float required = max(params.densityAccuracy * sensed.y, params.minDensity);
        uint found;
        accept = densityAcceptance(currentDensity(p.position, decodeOctahedral(p.normal), found), required);
        if (params.redistribute != 0u && required > 0.0f) {
            // Kept at its own power, or its power handed to its neighbours; a photon with no
            // stored neighbour is kept (nothing could take its power). Where no density is
            // required at all, Russian roulette below keeps a fraction epsilon instead: handing
            // power on there would keep one photon per search disk all over the scene.
            if (found == 0u || xi < accept) return;
            redistribute(photonRelativePower(p), found);
            slots[slot] = emptyPhoton();
            return;
        }
        // Russian roulette against an over-dense region: the weight 1 / p stays below
        // 1 / densityFloor, so the map's photons keep nearly equal powers (Suykens & Willems saw
        // the variance grow with the weights).
        if (required > 0.0f) accept = max(accept, params.densityFloor);
    } else {
        accept = importanceAcceptance(sensed.x, params.importanceScale);
    }
    accept = flooredAcceptance(accept, params.epsilon, params.cutoff != 0u);
    if (xi < accept) {
        vec3 power = min(photonRelativePower(p) / accept, vec3(kMaxHalfFloat));
        slots[slot] = withRelativePower(p, power);
    } else {
        slots[slot] = emptyPhoton();
    }
}

void main() {
    deposit();
    countTerminations(kTerminationGathers);  // rays and gathers this invocation's bounds cut short
}
