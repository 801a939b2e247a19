// Density control's redistribution (Suykens & Willems 2000, §3.1), after each round's decisions:
// adds the power that rejected photons handed to each photon of the map's grid to that photon in
// the map (the grid's sorted slots lead back to it) and clears the sum for the next round.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/deposit.glsl"
#include "shared/importance.glsl"
#include "shared/photon.glsl"

layout(local_size_x = kDepositGroupSize) in;

#include "common/item_index.glsl"
#include "common/segmented_arrays.glsl"

// The map, the grid's sorted slots and the power handed on (words 3 i .. 3 i + 2 for grid photon
// i): segmented arrays (segmented.glsl).
SEGMENTED_ARRAY(kRedistributeMapBinding, Map, mapTable);
SEGMENTED_ARRAY(kRedistributeSortedSlotBinding, SortedSlots, sortedSlotTable);
SEGMENTED_ARRAY(kRedistributeRedistributedBinding, Redistributed, redistributedTable);

layout(push_constant) uniform Push { RedistributeParams params; };

void main() {
    uint i = itemIndex();
    if (i >= params.gridPhotons) return;
    uvec3 added = uvec3(UINT_AT(redistributedTable, 3u * i), UINT_AT(redistributedTable, 3u * i + 1u),
                        UINT_AT(redistributedTable, 3u * i + 2u));
    if (added == uvec3(0u)) return;
    uint slot = UINT_AT(sortedSlotTable, i);
    GpuPhoton p = PHOTON_AT(mapTable, slot);
    vec3 power = photonRelativePower(p) + vec3(added) / kRedistributedFixedPoint;
    PHOTON_AT(mapTable, slot) = withRelativePower(p, min(power, vec3(kMaxHalfFloat)));
    UINT_AT(redistributedTable, 3u * i) = 0u;
    UINT_AT(redistributedTable, 3u * i + 1u) = 0u;
    UINT_AT(redistributedTable, 3u * i + 2u) = 0u;
}
