// Exact change detection of a selective photon update (interface: shared/kernels/selective_mark.glsl;
// host/photon/selective_mark_pass.h). One invocation per path: its track (shared/path_track.glsl)
// against every changed region (old and new bounds of a moved instance) and its light against the
// changed lights. A path that meets one is stale; its bit stays set until the host retraces it.
// Every stale path (found now or left from earlier frames) gets a weight, by which the host orders
// the retracing: the light its stored photons carry, weighted by whether they lie in the camera's
// view, plus the light it may bring where it meets a changed region (1 in view), the energy and
// view criteria of Dmitriev et al. 2002 §5.3.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/selective_mark.glsl"
#include "shared/path_track.glsl"
#include "shared/photon.glsl"
#include "shared/sampling.glsl"

#include "common/item_index.glsl"
#include "common/segmented_arrays.glsl"

layout(local_size_x = kSelectiveMarkGroupSize) in;

layout(buffer_reference, std430, buffer_reference_align = 16) buffer TrackSegment { GpuPathTrack items[]; };
#define TRACK_AT(table, i) TrackSegment(SEGMENT_ADDRESS_(table, i)).items[INDEX_IN_SEGMENT_(table, i)]

SEGMENTED_ARRAY(kSelectiveMarkTrackBinding, Tracks, trackTable);
SEGMENTED_ARRAY(kSelectiveMarkSlotBinding, Slots, slotTable);
layout(std430, set = 0, binding = kSelectiveMarkRegionBinding) readonly buffer Regions { vec4 regions[]; };
layout(std430, set = 0, binding = kSelectiveMarkLightBinding) readonly buffer Lights { uint changedLights[]; };
layout(std430, set = 0, binding = kSelectiveMarkStaleBinding) buffer Stale { uint stale[]; };
layout(std430, set = 0, binding = kSelectiveMarkWeightBinding) writeonly buffer Weights { uint weights[]; };
layout(std430, set = 0, binding = kSelectiveMarkCounterBinding) buffer Counters { uint counters[]; };

layout(push_constant) uniform Push { SelectiveMarkParams params; };

float viewWeight(vec3 p) {
    return params.useCamera == 0u || inCameraView(params.camera, p) ? 1.0f : kSelectiveOutOfView;
}

void main() {
    uint path = itemIndex();
    if (path >= params.pathCount) return;
    uint bit = 1u << (path & 31u);
    bool wasStale = (stale[path >> 5u] & bit) != 0u;
    GpuPathTrack track = TRACK_AT(trackTable, path);

    bool found = false;
    float arrival = 0.0f;  // the light the path may bring where it meets a change
    uint light = pathTrackLight(track);
    if (light < params.lightCount && (changedLights[light >> 5u] & (1u << (light & 31u))) != 0u) {
        found = true;
        arrival = kSelectiveOutOfView;
    }
    for (uint r = 0u; r < params.regionCount; ++r) {
        vec3 lo = regions[2u * r].xyz;
        vec3 hi = regions[2u * r + 1u].xyz;
        if (arrival < 1.0f && pathTrackMeetsBox(track, lo, hi)) {
            found = true;
            arrival = max(arrival, viewWeight(0.5f * (lo + hi)));
        }
    }
    if (!found && !wasStale) return;
    if (found && !wasStale) {
        atomicOr(stale[path >> 5u], bit);
        atomicAdd(counters[kSelectiveMarkCounterFound], 1u);
    }
    atomicAdd(counters[kSelectiveMarkCounterStale], 1u);
    // The light its stored photons carry away from where they are (if retraced).
    float weight = found ? arrival : kSelectiveOutOfView;
    uint first = path * params.maxDeposits;
    for (uint k = 0u; k < params.maxDeposits; ++k) {
        GpuPhoton p = PHOTON_AT(slotTable, first + k);
        if ((photonFlags(p) & kPhotonValid) == 0u) continue;
        weight += luminance(photonRelativePower(p)) * viewWeight(p.position);
    }
    weights[path] = uint(min(weight, kSelectiveMaxPathWeight) * kSelectiveWeightScale);
}
