// Caustics at the visible points (Jensen's L_caustic; shared/papers/004): the caustic map's
// photons within a fixed radius, weighted by the BSDF and the cone filter,
// L = sum f_r dPhi w / ((1 - 2/(3k)) pi r^2), times the camera path's throughput, added to the film.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_estimates.glsl"
#include "render/scene_access.glsl"
#include "photon/visible_point_access.glsl"
#include "shared/photon_render.glsl"
#define PHOTON_GRID_BINDING kCausticEstimateGridBinding
#include "photon/photon_gather.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

layout(std430, set = 0, binding = kCausticEstimateFilmBinding) buffer Film { vec4 film[]; };
layout(std430, set = 0, binding = kCausticEstimatePointBinding) readonly buffer VisiblePoints { GpuVisiblePoint visiblePoints[]; };

layout(push_constant) uniform Push { CausticEstimateParams params; };

void estimateCaustics() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    GpuVisiblePoint vp = visiblePoints[pixel];
    if ((vp.flags & kVisiblePointValid) == 0u) return;
    VisibleSurface s = visibleSurface(vp);
    FixedRadiusGather g = gatherFixedRadius(params.grid, vp.position, params.radius, params.coneK, kPhotonCaustic, 0u,
                                            s.bsdf, s.wo, s.t, s.b, s.n);
    vec3 radiance = g.weightedPower * (params.grid.photonPower / coneFilterArea(params.radius, params.coneK));
    film[pixel] += vec4(finiteOrZero(vp.throughput * radiance), 0.0f);
}

void main() {
    estimateCaustics();
    countTerminations(kTerminationGathers);  // rays and gathers this invocation's bounds cut short
}
