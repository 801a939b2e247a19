// For every photon slot: the visual importance density at the photon and the largest path
// importance of the importons around it (Suykens & Willems: the smallest allowable error, so the
// largest required density, of the nearby paths; from the finest kPathImportanceLevels levels only),
// from the finest cell of the importance grid
// (shared/importance.glsl) that holds k importons in the photon's normal bin — importons on
// surfaces facing another way, such as the other side of a wall, do not count. Empty slots, and
// photons of kinds the map does not keep, get zeros.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/importons.glsl"
#include "shared/normal_bins.glsl"
#include "shared/importance.glsl"
#include "shared/photon.glsl"

layout(local_size_x = kImportonGroupSize) in;

layout(std430, set = 0, binding = kImportanceLookupTableBinding) readonly buffer Table { ImportanceCell table[]; };
layout(std430, set = 0, binding = kImportanceLookupSlotBinding) readonly buffer Slots { GpuPhoton slots[]; };
layout(std430, set = 0, binding = kImportanceLookupImportanceBinding) writeonly buffer Importance { vec2 importance[]; };  // density, max path importance

layout(push_constant) uniform Push { ImportanceGridParams params; };

// The table's entry of a cell, or -1.
int findCell(ivec3 c, uint level, uint bin) {
    uint key = importanceKey(c, level, bin);
    uint index = importanceSlotHash(c, level, bin) & params.tableMask;
    for (uint probe = 0u; probe < kImportanceMaxProbes; ++probe) {
        uint stored = table[index].key;
        if (stored == key) return int(index);
        if (stored == kImportanceEmptyKey) return -1;
        index = (index + 1u) & params.tableMask;
    }
    return -1;
}

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount) return;
    GpuPhoton p = slots[slot];
    vec2 result = vec2(0.0f);
    if (photonSelected(photonFlags(p), params.requiredFlags, params.rejectedFlags)) {
        uint bin = normalBin(decodeOctahedral(p.normal));
        for (uint level = 0u; level < kImportanceLevels; ++level) {
            int entry = findCell(importanceCell(p.position, params.invCellSize, level), level, bin);
            if (entry < 0) continue;
            ImportanceCell cell = table[entry];
            float cellSize = float(1u << level) / params.invCellSize;
            // The path importance is a largest value, not a density: coarse cells would spread it
            // far from its importons (into rooms behind walls), so it is read near them only.
            result = vec2(float(cell.importance) / (kImportanceFixedPoint * cellSize * cellSize),
                          level < kPathImportanceLevels ? uintBitsToFloat(cell.maxPathImportance) : 0.0f);
            if (cell.count >= params.k) break;
        }
    }
    importance[slot] = result;
}
