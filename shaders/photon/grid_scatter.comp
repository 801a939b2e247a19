// Photon grid build, step 3 (after the prefix sum of the counts, cursor = a copy of cellStart):
// writes each selected photon's slot into its bucket's range. The order inside a bucket depends
// on scheduling; grid_sort_cells.comp makes it deterministic.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "photon/grid_build_bindings.glsl"

layout(local_size_x = kGridGroupSize) in;

void main() {
    uint slot = itemIndex();
    if (slot >= params.slotCount) return;
    uint bucket = bucketOfSlot(slot);
    if (bucket == ~0u) return;
    uint sorted = atomicAdd(cursor[bucket], 1u);  // once: SORTED_SLOT names its index twice
    SORTED_SLOT(sorted) = slot;
}
