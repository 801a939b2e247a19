// Precomputed radiance estimates (Christensen 1999): one invocation per radiance photon takes
// every stride-th photon of the global map (in grid order, which mixes the scene evenly) and
// stores the irradiance of its k nearest photons of every kind, E = sum dPhi / (pi r^2), as the
// record's power. Final gather rays read the nearest radiance photon (final_gather.comp).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/sampling.glsl"
#include "shared/bsdf.glsl"
#include "shared/photon_render.glsl"
#define PHOTON_GRID_BINDING 0
#include "photon_gather.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 2) writeonly buffer RadiancePhotons { GpuPhoton radiancePhotons[]; };

layout(push_constant) uniform Push { RadiancePhotonParams params; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    uint source = index * params.stride;
    if (source >= params.photonCount) return;
    GpuPhoton p = gridPhotons[source];
    vec3 n = decodeOctahedral(p.normal);
    float radius2;
    uint found = gatherNearest(params.grid, p.position, n, params.k, params.maxRadius, 0u, 0u, radius2);
    vec3 sum = vec3(0.0f);
    for (uint j = 0u; j < found; ++j) sum += photonRelativePower(gridPhotons[heapIndex[j]]);
    vec3 irradiance = sum * (params.grid.photonPower / (kPi * radius2));
    radiancePhotons[index] = makePhoton(p.position, irradiance, n, n, kPhotonValid, p.lightIndex);
}
