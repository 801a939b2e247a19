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
#include "render/scene_access.glsl"
#include "render/path_vertex.glsl"
#include "shared/halton.glsl"
#include "photon/visible_point_access.glsl"
#include "shared/photon_render.glsl"
#define PHOTON_GRID_BINDING kFinalGatherGridBinding
#include "photon/photon_gather.glsl"
#define GUIDE_CACHE_CELLS_BINDING kFinalGatherGuideCellsBinding
#define GUIDE_CACHE_CDFS_BINDING kFinalGatherGuideCdfsBinding
#include "guiding/guide_cache_access.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

layout(std430, set = 0, binding = kFinalGatherFilmBinding) buffer Film { vec4 film[]; };
layout(std430, set = 0, binding = kFinalGatherPointBinding) readonly buffer VisiblePoints { GpuVisiblePoint visiblePoints[]; };
layout(std430, set = 0, binding = kFinalGatherSampleBinding) writeonly buffer GatherSamples { GatherSample gatherSamples[]; };

layout(push_constant) uniform Push { FinalGatherParams params; };

const uint kFinalGatherStream = 0x46474154u;  // "FGAT"

// A direction at the visible point and its weight f cos / pdf: with probability `mix` from the
// guiding cache's grid (Jensen 1995: the photons' incoming flux; shared/papers/001), else from the
// BSDF, weighted by the mixture density mix p_grid + (1 - mix) p_bsdf (one-sample MIS, the
// balance heuristic), so the estimate stays that of BSDF sampling in expectation. Returns false
// for no direction (the BSDF's delta lobes, which the visible point does not follow). `pdf`: the
// density that chose `dir` (solid angle), which gather_reuse.comp divides other pixels' BSDFs by.
bool sampleGatherDirection(VisibleSurface s, vec3 position, bool frontFace, inout Sampler rng, out vec3 dir, out vec3 weight,
                           out float pdf) {
    float uLobe = nextSample(rng);
    vec2 point = nextSample2(rng);  // the direction (and the branch) from one stratified 2-D point
    dir = vec3(0.0f);
    weight = vec3(0.0f);
    pdf = 0.0f;
    float mix = 0.0f;
    CachedGuide cached;
    uint cdfBase = 0u;  // the cached grid's CDF, read in place
    uint gm = params.guide.gridSize & 0xffu;
    uint gn = (params.guide.gridSize >> 8u) & 0xffu;
    if (params.guide.mix > 0.0f && !specularIsDelta(s.bsdf) && s.bsdf.transmission == 0.0f) {
        cached = findCachedGuide(params.guide.grid, position, s.n);
        if (cached.found) {
            mix = cachedGuideMix(cached, s.n, params.guide.mix);
            cdfBase = cachedGuideCdfBase(cached);
        }
    }
    // One evaluation of the BSDF's density and value serves both branches (lavapipe runs the code
    // of both sides of a branch, so a second one costs every gather).
    BsdfSample bs;
    if (mix > 0.0f && guideChosen(point, mix)) {
        bs.wi = toLocal(toWorld(cachedGuideSample(cdfBase, gm, gn, point), cached.t, cached.b, cached.n), s.t, s.b, s.n);
        bs.lobe = kLobeDiffuse;
    } else {
        bs = sampleBsdfDirection(s.bsdf, s.wo, frontFace, true, vec3(uLobe, point));
    }
    // Delta lobes (and the dielectric layers, all sampled as Dirac lobes here) are not followed.
    if (!bsdfSampleUnweighted(bs) || bs.wi.z <= 0.0f) return false;
    pdf = pdfBsdf(s.bsdf, s.wo, bs.wi);
    if (mix > 0.0f) {
        vec3 wiGrid = toLocal(toWorld(bs.wi, s.t, s.b, s.n), cached.t, cached.b, cached.n);
        pdf = mix * cachedGuidePdf(cdfBase, gm, gn, wiGrid) + (1.0f - mix) * pdf;
    }
    if (!(pdf > 0.0f)) return false;
    dir = normalize(toWorld(bs.wi, s.t, s.b, s.n));
    weight = evalBsdf(s.bsdf, s.wo, bs.wi) * (bs.wi.z / pdf);
    return true;
}

// The radiance arriving at the visible point along a gather direction (one sample of it: the
// global map read where the ray, after any delta bounces, first meets a surface that stores photons).
vec3 incomingRadiance(GpuVisiblePoint vp, vec3 dir, inout Sampler rng) {
    vec3 weight = vec3(1.0f);
    // Non-delta lobes reflect: the ray starts outside any medium.
    vec3 geometricNormal = decodeOctahedral(vp.geometricNormal);
    Ray ray = rayFrom(offsetRayOrigin(vp.position, geometricNormal, dir), dir);
    for (uint depth = 0u; depth <= params.maxSpecularDepth; ++depth) {
        PathVertex v;
        // Escaped: environment light here is direct light (next-event estimation's at the visible
        // point) or, behind delta bounces, the caustic map's.
        if (!traceVertex(ray, v)) return vec3(0.0f);
        weight *= v.transmittance;
        // A partly transmissive surface: with probability `transmission` the ray goes on through
        // its dielectric layer, otherwise it ends on the opaque layer (as in visible_points.comp).
        float transmissionShare = storesPhotons(v.bsdf) ? v.bsdf.transmission : 0.0f;
        bool throughLayer = transmissionShare > 0.0f && nextSample(rng) < transmissionShare;
        if (storesPhotons(v.bsdf) && !throughLayer) {
            weight /= 1.0f - transmissionShare;
            if (params.radianceLookup == 0u)
                return weight * radianceNearest(params.grid, v.hit.position, params.k, params.maxRadius, 0u, 0u, v.bsdf,
                                                v.wo, v.t, v.b, v.n);
            if (!findNearest(params.grid, v.hit.position, v.n, params.lookupRadius, 0u, 0u)) return vec3(0.0f);
            vec3 irradiance = photonRelativePower(gridPhoton(heapIndex[0])) * params.grid.photonPower;
            return weight * diffuseReflectance(v.bsdf, v.wo) * irradiance;
        }
        if (throughLayer) v.bsdf.transmission = 1.0f;
        if (depth == params.maxSpecularDepth) break;
        vec3 ud = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        BsdfSample next = sampleVertexBsdf(v, true, ud);
        if (next.lobe == kLobeNone) break;
        weight *= next.weight;
        spawnRay(v, next, ray);
    }
    return vec3(0.0f);
}

void finalGather() {
    uint pixel = gl_GlobalInvocationID.x;
    uint pixels = params.width * params.height;
    if (pixel >= pixels) return;
    GpuVisiblePoint vp = visiblePoints[pixel];
    if ((vp.flags & kVisiblePointValid) == 0u) return;
    VisibleSurface s = visibleSurface(vp);
    if (params.gatherRays == 0u) {
        vec3 radiance = radianceNearest(params.grid, vp.position, params.k, params.maxRadius, 0u,
                                        kPhotonPrimary | kPhotonCaustic, s.bsdf, s.wo, s.t, s.b, s.n);
        film[pixel] += vec4(finiteOrZero(vp.throughput * radiance), 0.0f);
        return;
    }
    Sampler rng = makePixelSampler(params.sampleIndex * params.gatherRays + params.rayIndex, params.samplerCount,
                                   hashCombine(hashCombine(params.seed, kFinalGatherStream), pixel));
    vec3 dir, weight;
    float pdf;
    bool sampled = sampleGatherDirection(s, vp.position, (vp.flags & kVisiblePointFrontFace) != 0u, rng, dir, weight, pdf);
    vec3 incoming = sampled ? incomingRadiance(vp, dir, rng) : vec3(0.0f);
    bool pooled = params.reuse != 0u && gatherReusable(s.bsdf);
    if (params.reuse != 0u) {
        GatherSample g;
        g.radianceOverPdf = !pooled ? vec3(-1.0f) : sampled ? finiteOrZero(incoming / pdf) : vec3(0.0f);
        g.direction = encodeOctahedral(sampled ? dir : vec3(0.0f, 0.0f, 1.0f));
        gatherSamples[params.rayIndex * pixels + pixel] = g;
    }
    if (!pooled) film[pixel] += vec4(finiteOrZero(vp.throughput * weight * incoming / float(params.gatherRays)), 0.0f);
}

void main() {
    finalGather();
    countTerminations(kTerminationGathers);  // rays and gathers this invocation's bounds cut short
}
