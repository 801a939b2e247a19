// For every photon slot: the visual importance density at the photon (the k nearest importons'
// importance over the disk that holds them, a k-nearest density estimate like the radiance
// estimate's) and the largest path importance among them (Suykens & Willems: the smallest
// allowable error, so the largest required density, of the nearby paths). Importons on
// surfaces facing away are not counted (the gather's normal test), so importance does not leak
// through walls. Empty slots, and photons of kinds the map does not keep, get zeros.
#version 460
#extension GL_GOOGLE_include_directive : require

#define PHOTON_GRID_BINDING 8
#include "scene_access.glsl"
#include "photon_gather.glsl"
#include "shared/importance.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 10) readonly buffer Slots { GpuPhoton slots[]; };
layout(std430, set = 0, binding = 11) writeonly buffer Importance { vec2 importance[]; };  // density, max path importance

layout(push_constant) uniform Push { ImportanceLookupParams params; };

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount) return;
    GpuPhoton p = slots[slot];
    vec2 result = vec2(0.0f);
    if (photonSelected(photonFlags(p), params.requiredFlags, params.rejectedFlags)) {
        float radius2;
        uint found = gatherNearest(params.importons, p.position, decodeOctahedral(p.normal), params.k, params.maxRadius,
                                   0u, 0u, radius2);
        float importance = 0.0f;
        float maxPath = 0.0f;
        for (uint j = 0u; j < found; ++j) {
            vec3 w = photonRelativePower(gridPhotons[heapIndex[j]]);
            importance += w.x;
            maxPath = max(maxPath, w.y);
        }
        result = vec2(importance / (kPi * radius2), maxPath);
    }
    importance[slot] = result;
}
