// Photon compaction, step 4 (one invocation): moves the map's end past the chunk's photons and
// counts those that did not fit.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "photon/compact.glsl"

layout(local_size_x = kCompactAdvanceGroupSize) in;

void main() {
    uint count = mapState[kPhotonMapStateCount];
    uint chunk = ranks[params.scannedCount];
    uint kept = min(chunk, params.capacity - min(count, params.capacity));
    mapState[kPhotonMapStateCount] = count + kept;
    mapState[kPhotonMapStateDropped] += chunk - kept;
}
