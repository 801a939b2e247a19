// Photon grid build, step 1: counts the selected photons per bucket (cellStart[bucket]).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "photon/grid_build_bindings.glsl"

layout(local_size_x = kGridGroupSize) in;

void main() {
    uint slot = itemIndex();
    if (slot >= params.slotCount) return;
    uint bucket = bucketOfSlot(slot);
    if (bucket != ~0u) atomicAdd(cellStart[bucket], 1u);
}
