// Photon compaction, step 1: ranks[slot] = 1 for every slot whose photon the map keeps, else 0.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "photon/compact.glsl"

layout(local_size_x = kCompactGroupSize) in;

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot <= params.scannedCount) ranks[slot] = slot < params.slotCount && slotKept(slot) ? 1u : 0u;
}
