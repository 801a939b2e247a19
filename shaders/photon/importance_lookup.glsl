// GLSL-only: reading the importance grid (shared/importance.glsl) at a point, for
// importance_lookup.comp (at photons) and importon_importance.comp (at importons). The includer
// declares the grid as `table` (ImportanceCell[]) and its ImportanceGridParams as `params`.
#ifndef VKP_IMPORTANCE_LOOKUP_GLSL
#define VKP_IMPORTANCE_LOOKUP_GLSL

#include "shared/normal_bins.glsl"
#include "shared/importance.glsl"

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

// The visual importance density at `position` and the largest path importance of the importons
// around it, from the finest cell holding params.k importons in the normal bin of `normal`
// (x: density, y: max path importance; zeros where no cell has importons).
vec2 importanceAround(vec3 position, vec3 normal) {
    vec2 result = vec2(0.0f);
    uint bin = normalBin(normal);
    for (uint level = 0u; level < kImportanceLevels; ++level) {
        int entry = findCell(importanceCell(position, params.invCellSize, level), level, bin);
        if (entry < 0) continue;
        ImportanceCell cell = table[entry];
        float cellSize = float(1u << level) / params.invCellSize;
        // The path importance is a largest value, not a density: coarse cells would spread it
        // far from its importons (into rooms behind walls), so it is read near them only.
        result = vec2(float(cell.importance) / (kImportanceFixedPoint * cellSize * cellSize),
                      level < kPathImportanceLevels ? uintBitsToFloat(cell.maxPathImportance) : 0.0f);
        if (cell.count >= params.k) break;
    }
    return result;
}

#endif
