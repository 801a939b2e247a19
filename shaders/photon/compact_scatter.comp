// Photon compaction, step 3 (after the exclusive scan of the marks): appends each kept photon at
// the map's current end plus its rank in the chunk, so the map is in slot order on every run.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "photon/compact.glsl"

layout(local_size_x = kCompactGroupSize) in;

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount || !slotKept(slot)) return;
    uint index = mapState[kPhotonMapStateCount] + ranks[slot];
    if (index < params.capacity) PHOTON_AT(mapTable, index) = slots[slot];
}
