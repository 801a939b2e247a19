// GLSL-only bindings of the photon compaction kernels (host/photon/photon_compaction.h): the
// selected photons of a chunk's fixed slots are appended, in slot order, to a dense photon map.
#ifndef VKP_COMPACT_GLSL
#define VKP_COMPACT_GLSL

#include "shared/kernels/compaction.glsl"
#include "shared/photon.glsl"
#include "shared/photon_grid.glsl"

layout(std430, set = 0, binding = kCompactSlotBinding) readonly buffer Slots { GpuPhoton slots[]; };
// scannedCount + 1 entries: 1 per kept slot (0 past the chunk), then (scanned) each kept slot's
// rank in the chunk; ranks[scannedCount] ends as the chunk's number of kept photons.
layout(std430, set = 0, binding = kCompactRankBinding) buffer Ranks { uint ranks[]; };
#include "common/segmented_arrays.glsl"

// The dense map: a segmented array (segmented.glsl), so it may outgrow one buffer.
SEGMENTED_ARRAY(kCompactMapBinding, Map, mapTable);
layout(std430, set = 0, binding = kCompactStateBinding) buffer MapState { uint mapState[]; };  // kPhotonMapState*

layout(push_constant) uniform Push { PhotonCompactParams params; };

bool slotKept(uint slot) {
    return photonSelected(photonFlags(slots[slot]), params.requiredFlags, params.rejectedFlags);
}

#endif
