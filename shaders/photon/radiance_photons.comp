// Precomputed radiance estimates (Christensen 1999): one invocation per photon of the global map
// (in grid order) makes about every stride-th photon (radiancePhotonChosen), the first of every
// bucket and every photon of a sparse bucket a radiance photon holding the irradiance of its k
// nearest photons of every kind, E = sum dPhi / (pi r^2), as the record's power, in the photon's
// own slot; the other slots stay empty. Final gather rays read the nearest radiance photon
// (final_gather.comp).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_estimates.glsl"
#include "shared/sampling.glsl"
#define VKP_NO_BSDF_TABLES  // converts no irradiance: final_gather.comp applies the BSDF
#include "shared/bsdf.glsl"
#include "shared/photon_render.glsl"
#define PHOTON_GRID_BINDING kRadiancePhotonsGridBinding
#include "photon/photon_gather.glsl"
#include "common/termination_counters.glsl"
#include "common/item_index.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

SEGMENTED_ARRAY(kRadiancePhotonsOutputBinding, RadiancePhotons, radiancePhotonTable);

layout(push_constant) uniform Push { RadiancePhotonParams params; };

void radiancePhoton() {
    uint source = itemIndex();
    if (source >= params.photonCount) return;
    GpuPhoton p = gridPhoton(source);
    // About every stride-th photon, chosen by its own record (radiancePhotonChosen: unchanged
    // photons keep their choice from frame to frame), the first photon of every bucket and every
    // photon of a bucket holding fewer than stride: every bucket with a photon gets a radiance
    // photon, and a final-gather ray finds one wherever the map has photons within a cell.
    uint bucket = gridHash(gridCell(p.position, params.grid.invCellSize), params.grid.tableMask);
    uint inBucket = gridCellStart[bucket + 1u] - gridCellStart[bucket];
    bool chosen = inBucket < params.stride || source == gridCellStart[bucket] || radiancePhotonChosen(p, params.stride);
    if (!chosen) {
        PHOTON_AT(radiancePhotonTable, source) = makePhoton(vec3(0.0f), vec3(0.0f), vec3(0.0f, 0.0f, 1.0f), vec3(0.0f, 0.0f, 1.0f), 0u, 0u);
        return;
    }
    vec3 n = decodeOctahedral(p.normal);
    float radius2;
    uint found = gatherNearest(params.grid, p.position, n, params.k, params.maxRadius, 0u, 0u, radius2);
    vec3 sum = vec3(0.0f);
    for (uint j = 0u; j < found; ++j) sum += photonRelativePower(gridPhoton(heapIndex[j]));
    vec3 irradiance = sum * (params.grid.photonPower * nearestEstimateScale(found, clamp(params.k, 1u, kMaxGatherK)) /
                             (kPi * radius2));
    PHOTON_AT(radiancePhotonTable, source) = makePhoton(p.position, irradiance, n, n, kPhotonValid, p.lightIndex);
}

void main() {
    radiancePhoton();
    countTerminations(kTerminationGathers);  // rays and gathers this invocation's bounds cut short
}
