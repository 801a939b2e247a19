// Stochastic progressive photon mapping (Hachisuka & Jensen 2009), one photon pass: at each
// pixel's visible point of this pass, the M photons of this pass within the pixel's radius R
// (direct photons excluded: next-event estimation adds direct light) give
// Phi = sum f_r dPhi; then N' = N + alpha M, R'^2 = R^2 (N + alpha M) / (N + M) and
// tau' = (tau + throughput Phi) R'^2 / R^2 (eq. 5-7, photon_estimate.glsl). After P passes the
// pixel's indirect and caustic radiance is tau / (P pi R^2): consistent, the bias vanishes as R
// shrinks.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_estimates.glsl"
#include "render/scene_access.glsl"
#include "photon/visible_point_access.glsl"
#include "shared/photon_estimate.glsl"
#include "shared/photon_render.glsl"
#define PHOTON_GRID_BINDING kSppmUpdateGridBinding
#include "photon/photon_gather.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

layout(std430, set = 0, binding = kSppmUpdatePixelBinding) buffer Pixels { SppmPixel pixels[]; };
layout(std430, set = 0, binding = kSppmUpdatePointBinding) readonly buffer VisiblePoints { GpuVisiblePoint visiblePoints[]; };

layout(push_constant) uniform Push { SppmParams params; };

void updatePixel() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    GpuVisiblePoint vp = visiblePoints[pixel];
    if ((vp.flags & kVisiblePointValid) == 0u) return;
    SppmPixel state = pixels[pixel];
    VisibleSurface s = visibleSurface(vp);
    FixedRadiusGather g = gatherFixedRadius(params.grid, vp.position, sqrt(state.radius2), 0.0f, 0u, kPhotonPrimary,
                                            s.bsdf, s.wo, s.t, s.b, s.n);
    vec3 phi = finiteOrZero(vp.throughput * g.weightedPower * params.grid.photonPower);
    float fluxScale;
    float radius2 = progressiveRadiusUpdate(state.radius2, state.photons, float(g.count), params.alpha, fluxScale);
    state.flux = (state.flux + phi) * fluxScale;
    state.radius2 = radius2;
    pixels[pixel] = state;
}

void main() {
    updatePixel();
    countTerminations(kTerminationGathers);  // rays and gathers this invocation's bounds cut short
}
