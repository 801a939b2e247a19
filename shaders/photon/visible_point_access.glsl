// GLSL-only: the surface of a visible point (shared/visible_point.glsl) as the estimate passes
// need it — BSDF parameters, shading frame and local outgoing direction. Include after
// scene_access.glsl.
#ifndef VKP_VISIBLE_POINT_ACCESS_GLSL
#define VKP_VISIBLE_POINT_ACCESS_GLSL

#include "render/path_vertex.glsl"
#include "shared/photon.glsl"
#include "shared/visible_point.glsl"

struct VisibleSurface {
    BsdfParams bsdf;
    vec3 t;
    vec3 b;
    vec3 n;      // shading normal on the arrival side
    vec3 wo;     // local
};

VisibleSurface visibleSurface(GpuVisiblePoint vp) {
    VisibleSurface s;
    // The textures at the levels the camera path read them (traceVertex).
    SurfaceHit hit = surfaceAt(vp.triangle, vp.barycentrics.x, vp.barycentrics.y, -decodeOctahedral(vp.wo), vp.coneWidth);
    s.bsdf = bsdfParamsAtHit(materials[vp.material], hit);
    s.n = decodeOctahedral(vp.shadingNormal);
    shadingFrame(s.n, decodeOctahedral(vp.wo), s.t, s.b, s.wo);  // as traceVertex set it up
    applyCoatNormal(s.bsdf, hit, s.t, s.b, s.n);
    applyAnisotropy(s.bsdf, hit, s.t, s.b);
    return s;
}

// Whether a visible point's final-gather rays may serve its neighbours, and theirs it
// (gather_reuse.comp): a BSDF broad enough that rays drawn from another pixel's density estimate
// its integral with little variance. No transmission (those gathers follow the dielectric layer),
// isotropic, a specular lobe and a coat of perceptual roughness 0.5 or more.
bool gatherReusable(BsdfParams p) {
    return p.transmission == 0.0f && !isAnisotropic(p) && p.roughness >= 0.5f &&
           (p.clearcoat == 0.0f || p.clearcoatRoughness >= 0.5f);
}

vec3 finiteOrZero(vec3 v) {
    return any(isnan(v)) || any(isinf(v)) ? vec3(0.0f) : v;
}

#endif
