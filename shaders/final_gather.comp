// Indirect light at the visible points by final gathering (Jensen's L_indirect; shared/papers/004):
// this dispatch adds one of `gatherRays` BSDF-sampled rays per visible point. The ray follows
// delta bounces (mirrors, glass) to the first surface with a diffuse or glossy part and reads
// the global map there: the k nearest photons of every kind (direct, caustic and indirect light
// all arrive at that surface), or, with radiance photons (radiance_photons.comp), the irradiance
// precomputed at the nearest of them times the surface's diffuse reflectance. Emission found by
// the ray is not added: direct light is next-event
// estimation's and light through delta bounces is the caustic map's.
//
// With gatherRays = 0 the global map is read at the visible point itself, with primary and
// caustic photons excluded (those parts come from next-event estimation and the caustic map).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_estimates.glsl"
#include "scene_access.glsl"
#include "shared/halton.glsl"
#include "visible_point_access.glsl"
#include "shared/photon_render.glsl"
#define PHOTON_GRID_BINDING kFinalGatherGridBinding
#include "photon_gather.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

layout(std430, set = 0, binding = kFinalGatherFilmBinding) buffer Film { vec4 film[]; };
layout(std430, set = 0, binding = kFinalGatherPointBinding) readonly buffer VisiblePoints { GpuVisiblePoint visiblePoints[]; };

layout(push_constant) uniform Push { FinalGatherParams params; };

const uint kFinalGatherStream = 0x46474154u;  // "FGAT"

// Radiance arriving at the visible point along one BSDF-sampled direction, divided by its pdf
// and multiplied by f cos (the sample's weight).
vec3 gatherRay(GpuVisiblePoint vp, VisibleSurface s, inout Sampler rng) {
    vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
    BsdfSample bs = sampleBsdf(s.bsdf, s.wo, (vp.flags & kVisiblePointFrontFace) != 0u, true, u);
    // The visible point's delta lobes are not followed (as in visible_points.comp).
    if (bs.lobe == kLobeNone || (bs.lobe & kLobeDelta) != 0u) return vec3(0.0f);
    vec3 weight = bs.weight;
    vec3 dir = normalize(toWorld(bs.wi, s.t, s.b, s.n));
    vec3 origin = offsetRayOrigin(vp.position, decodeOctahedral(vp.geometricNormal), dir);
    vec3 mediumSigma = vec3(0.0f);  // non-delta lobes reflect: the ray starts outside any medium
    for (uint depth = 0u; depth <= params.maxSpecularDepth; ++depth) {
        float tHit;
        uint tri;
        float b1;
        float b2;
        if (!traceClosest(origin, dir, kInfinity, tHit, tri, b1, b2)) return vec3(0.0f);
        weight *= exp(-mediumSigma * tHit);
        SurfaceHit hit = surfaceAt(tri, b1, b2, dir);
        GpuMaterial material = materials[hit.material];
        BsdfParams bsdf = bsdfParamsAt(material, hit.uv);
        vec3 n = hit.frontFace ? hit.shadingNormal : -hit.shadingNormal;
        vec3 t;
        vec3 b;
        orthonormalBasis(n, t, b);
        vec3 wo = toLocal(-dir, t, b, n);
        if (wo.z <= 0.0f) wo.z = 1.0e-4f;
        if (storesPhotons(bsdf)) {
            if (params.radianceLookup == 0u)
                return weight * radianceNearest(params.grid, hit.position, params.k, params.maxRadius, 0u, 0u, bsdf,
                                                wo, t, b, n);
            float radius2;
            if (gatherNearest(params.grid, hit.position, n, 1u, params.lookupRadius, 0u, 0u, radius2) == 0u)
                return vec3(0.0f);
            vec3 irradiance = photonRelativePower(gridPhotons[heapIndex[0]]) * params.grid.photonPower;
            return weight * diffuseReflectance(bsdf, wo) * irradiance;
        }
        if (depth == params.maxSpecularDepth) break;
        vec3 ud = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        BsdfSample next = sampleBsdf(bsdf, wo, hit.frontFace, true, ud);
        if (next.lobe == kLobeNone) break;
        weight *= next.weight;
        dir = normalize(toWorld(next.wi, t, b, n));
        origin = offsetRayOrigin(hit.position, hit.geometricNormal, dir);
        if ((next.lobe & kLobeTransmission) != 0u && (material.flags & kMaterialThinWalled) == 0u)
            mediumSigma = hit.frontFace ? material.attenuationCoeff : vec3(0.0f);
    }
    return vec3(0.0f);
}

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    GpuVisiblePoint vp = visiblePoints[pixel];
    if ((vp.flags & kVisiblePointValid) == 0u) return;
    VisibleSurface s = visibleSurface(vp);
    vec3 radiance;
    if (params.gatherRays == 0u) {
        radiance = radianceNearest(params.grid, vp.position, params.k, params.maxRadius, 0u,
                                   kPhotonPrimary | kPhotonCaustic, s.bsdf, s.wo, s.t, s.b, s.n);
    } else {
        Sampler rng = makeSampler(params.sampleIndex * params.gatherRays + params.rayIndex,
                                  hashCombine(hashCombine(params.seed, kFinalGatherStream), pixel));
        radiance = gatherRay(vp, s, rng) / float(params.gatherRays);
    }
    film[pixel] += vec4(finiteOrZero(vp.throughput * radiance), 0.0f);
}
