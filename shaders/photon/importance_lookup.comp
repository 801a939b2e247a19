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

#include "photon/importance_lookup.glsl"

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount) return;
    GpuPhoton p = slots[slot];
    vec2 result = vec2(0.0f);
    if (photonSelected(photonFlags(p), params.requiredFlags, params.rejectedFlags))
        result = importanceAround(p.position, decodeOctahedral(p.normal));
    importance[slot] = result;
}
