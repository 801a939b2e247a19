// The path tracer, included by pathtrace.comp (the reference) and guided_pathtrace.comp (with
// GUIDED defined: photon-guided direction sampling, shared/guiding.glsl). Next-event estimation
// on all lights combined with BSDF sampling by multiple importance sampling (power heuristic),
// Russian roulette, Beer-Lambert absorption inside KHR_materials_volume solids. One invocation
// per pixel adds `sampleCount` samples to the film; a pixel is written by exactly one invocation,
// so accumulation is deterministic.
// With --direct raster (kPathFlagRaster*), the first vertex's direct light from the covered lights
// comes from the raster pass (binding 10, added to every sample) instead of next-event estimation,
// and emission of covered area lights reached by a BSDF sample from the first vertex is dropped:
// the raster term already holds all of it (no double counting).
#ifndef VKP_PATH_TRACER_GLSL
#define VKP_PATH_TRACER_GLSL

#include "shared/kernels/path_trace.glsl"
#include "render/scene_access.glsl"
#include "shared/halton.glsl"
#ifdef GUIDED
// Next-event estimation weighs its light samples against the density with which this tracer
// samples directions: the guided mixture's (guidedDirectionPdf, below), not the BSDF's alone.
#include "render/path_vertex.glsl"
float guidedDirectionPdf(PathVertex v, vec3 wi);
#define CAMERA_PATH_DIRECTION_PDF guidedDirectionPdf
#endif
#include "render/camera_and_lights.glsl"

layout(local_size_x = kPathTraceGroupSize) in;

layout(std430, set = 0, binding = kPathTraceFilmBinding) buffer Film { vec4 film[]; };  // rgb sum, sample count
layout(std430, set = 0, binding = kPathTraceCounterBinding) buffer Counters { uint counters[]; };
// counters[kPathTraceCounter*]: dropped non-finite samples, rays traced (shared/kernels/path_trace.glsl)
layout(std430, set = 0, binding = kPathTraceRasterDirectBinding) readonly buffer RasterDirect { vec4 rasterDirect[]; };

#ifdef GUIDED
#include "shared/guiding.glsl"
#ifdef GUIDE_CACHE
#define GUIDE_CACHE_CELLS_BINDING kPathTraceGuideCellsBinding
#define GUIDE_CACHE_CDFS_BINDING kPathTraceGuideCdfsBinding
#include "guiding/guide_cache_access.glsl"
layout(std430, set = 0, binding = kPathTraceGuideIrradianceBinding) readonly buffer CacheIrradiance { vec4 cacheIrradiance[]; };
#ifdef GUIDE_LEARN
#define GUIDE_LEARN_SUMS_BINDING kPathTraceGuideLearnBinding
#endif
#else
#define PHOTON_GRID_BINDING kPathTraceGuideBinding
#include "photon/photon_gather.glsl"
#endif
layout(push_constant) uniform Push { PathTraceParams params; GuideParams guide; };
#else
layout(push_constant) uniform Push { PathTraceParams params; };
#endif

// The state of one camera path between bounces.
struct PathState {
    Ray ray;           // towards the next vertex
    vec3 throughput;
    vec3 radiance;
    float lastPdf;     // solid-angle pdf of the last BSDF sample (for MIS at emitters)
    bool lastDelta;    // camera rays and delta lobes: emission is added unweighted
    vec3 lastPosition; // the last vertex and its shading normal, where MIS recomputes the light pdf
    vec3 lastNormal;
    float reference;   // guide-driven Russian roulette: the pixel's estimated value (< 0: not yet)
    float unguidedScale; // product over the path's guided vertices of mixture / BSDF density: the
                         // throughput times it is what BSDF sampling would have carried (roulette)
    uint depth;
    Sampler rng;
};

PathState startPath(uint sampleIndex, uint streamSeed, uint px, uint py) {
    PathState st;
    st.rng = makePixelSampler(sampleIndex, params.camera.pixelSamples, streamSeed);
    vec2 jitter = nextSample2(st.rng);
    if ((params.flags & kPathFlagPixelCentres) != 0u) jitter = vec2(0.5f);
    vec2 filmPixel = vec2(float(px) + jitter.x, float(py) + jitter.y);
    st.ray = cameraRay(params.camera, params.width, params.height, filmPixel);
    st.throughput = vec3(1.0f);
    st.radiance = vec3(0.0f);
    st.lastPdf = 0.0f;
    st.lastDelta = true;
    st.lastPosition = vec3(0.0f);
    st.lastNormal = vec3(0.0f);
    st.reference = -1.0f;
    st.unguidedScale = 1.0f;
    st.depth = 0u;
    return st;
}

#ifdef GUIDED
// Photon-guided sampling at surfaces without delta lobes (Jensen 1995): the k nearest photons of
// the guiding map (direct photons left out: next-event estimation covers direct light) weighted
// by f_r fill the grid; one-sample MIS picks the grid with probability guide.mix, else the BSDF,
// and weights by the mixture density, so neither a mis-estimated grid nor a narrow lobe can make
// the variance blow up. mix = 1 is the paper's method.
// The vertex's grid is made once (prepareGuide) before next-event estimation, whose MIS weight
// needs the same mixture density (guidedDirectionPdf) as the sample's own weight: with the BSDF's
// density there, the two weights of a light direction did not sum to one (a furnace read 0.75 %
// low with the cache, 3 % at mix 1).
struct VertexGuide {
    bool guided;      // the vertex samples the mixture (else the BSDF alone)
    float mix;        // probability of sampling the grid: guide.mix, or less (kCachedGuideMaxMix)
    uint m;           // grid size: m theta bands x n phi sectors
    uint n;
    vec3 t;           // the grid's frame: the shading frame, or the cache bin's axis frame
    vec3 b;
    vec3 normal;
    vec4 irradiance;  // the guiding photons' indirect irradiance (rgb; w 1 where there is an estimate)
    uint cdfBase;     // with the cache: where the grid's CDF starts in the cache (read in place)
};
VertexGuide vertexGuide;
#ifndef GUIDE_CACHE
float guideCdf[kMaxGuideCells];  // the vertex's grid, as a CDF (guideFinalize)
#endif

// The vertex grid's density of local direction wi (in the grid's frame), and a direction from it.
float vertexGuidePdf(vec3 wi) {
#ifdef GUIDE_CACHE
    return cachedGuidePdf(vertexGuide.cdfBase, vertexGuide.m, vertexGuide.n, wi);
#else
    return guidePdf(guideCdf, vertexGuide.m, vertexGuide.n, wi);
#endif
}
vec3 vertexGuideSample(vec2 u) {
#ifdef GUIDE_CACHE
    return cachedGuideSample(vertexGuide.cdfBase, vertexGuide.m, vertexGuide.n, u);
#else
    return guideSample(guideCdf, vertexGuide.m, vertexGuide.n, u);
#endif
}

void prepareGuide(PathVertex v) {
    vertexGuide.guided = false;
    vertexGuide.mix = guide.mix;
    vertexGuide.irradiance = vec4(0.0f);
    vertexGuide.cdfBase = 0u;
    if (guide.mix <= 0.0f || specularLobeIsDelta(v.bsdf) || v.bsdf.transmission > 0.0f || !storesPhotons(v.bsdf)) return;
    uint gm = guide.gridSize & 0xffu;
    uint gn = (guide.gridSize >> 8u) & 0xffu;
    vec3 gt = v.t;
    vec3 gb = v.b;
    vec3 gnrm = v.n;
#ifdef GUIDE_CACHE
    CachedGuide cached = findCachedGuide(guide.grid, v.hit.position, v.n);
    if (!cached.found) return;  // no grid here: the BSDF
    gnrm = cached.n;
    gt = cached.t;
    gb = cached.b;
    vertexGuide.mix = cachedGuideMix(cached, v.n, guide.mix);
    vertexGuide.cdfBase = cachedGuideCdfBase(cached);
    vec4 cachedIrradiance = cacheIrradiance[cached.bucket * kNormalBins + cached.bin];
    vertexGuide.irradiance = vec4(cachedIrradiance.rgb, 1.0f);
    uint photonsPerCell = guide.gridSize >> 16u;
    if (photonsPerCell > 0u) {
        uvec2 size = guideAdaptiveSize(gm, gn, photonsPerCell, cachedIrradiance.w);
        gm = size.x;
        gn = size.y;
    }
#else
    for (uint i = 0u; i < kMaxGuideCells; ++i) guideCdf[i] = 0.0f;
    float radius2;
    uint found = gatherNearest(guide.grid, v.hit.position, v.n, guide.k, guide.maxRadius, 0u, kPhotonPrimary, radius2);
    vec3 flux = vec3(0.0f);
    for (uint j = 0u; j < found; ++j) {
        GpuPhoton p = gridPhoton(heapIndex[j]);
        vec3 wi = toLocal(decodeOctahedral(p.direction), v.t, v.b, v.n);
        guideAdd(guideCdf, gm, gn, wi, luminance(evalVertexBsdf(v, wi) * photonRelativePower(p)));
        flux += photonRelativePower(p);
    }
    guideFinalize(guideCdf, gm, gn);
    vertexGuide.irradiance = vec4(flux * (guide.grid.photonPower / (kPi * radius2)), 1.0f);
#endif
    vertexGuide.guided = true;
    vertexGuide.m = gm;
    vertexGuide.n = gn;
    vertexGuide.t = gt;
    vertexGuide.b = gb;
    vertexGuide.normal = gnrm;
}

// The density with which sampleGuided produces local direction wi at the prepared vertex, given
// the BSDF's density there (bsdfPdf).
float guidedMixturePdf(PathVertex v, vec3 wi, float bsdfPdf) {
    if (!vertexGuide.guided) return bsdfPdf;
    vec3 wiGrid = toLocal(toWorld(wi, v.t, v.b, v.n), vertexGuide.t, vertexGuide.b, vertexGuide.normal);
    return vertexGuide.mix * vertexGuidePdf(wiGrid) + (1.0f - vertexGuide.mix) * bsdfPdf;
}
float guidedDirectionPdf(PathVertex v, vec3 wi) { return guidedMixturePdf(v, wi, pdfVertexMis(v, wi)); }

// A direction from the prepared vertex's mixture, weighted by the mixture density. u: the BSDF's
// lobe choice and the stratified 2-D point that picks the branch (guideChosen) and the direction.
// Unguided vertices sample the BSDF alone, as the path tracer does. Every branch shares one
// evaluation of the BSDF's density and value: lavapipe runs the code of both sides of a branch,
// and a second evaluation cost every vertex. A delta lobe (a smooth clearcoat over a rough base)
// is reached by the BSDF branch alone, with probability 1 - mix.
// densityRatio: the sample's mixture density over the BSDF's (1 at unguided vertices), which
// turns the guided throughput back into the one BSDF sampling would have carried.
BsdfSample sampleGuided(PathVertex v, vec3 u, out float densityRatio) {
    densityRatio = 1.0f;
    float mix = vertexGuide.guided ? vertexGuide.mix : 0.0f;
    BsdfSample s;
    vec2 point = u.yz;
    if (mix > 0.0f && guideChosen(point, mix)) {
        vec3 local = vertexGuideSample(point);
        s.wi = toLocal(toWorld(local, vertexGuide.t, vertexGuide.b, vertexGuide.normal), v.t, v.b, v.n);
        s.lobe = kLobeDiffuse;
        s.pdf = 0.0f;
        s.weight = vec3(0.0f);
    } else {
        s = sampleBsdfDirection(v.bsdf, v.wo, v.hit.frontFace, true, vec3(u.x, point));
    }
    s = keepOnSurfaceSide(v, s);
    if (!bsdfSampleUnweighted(s)) {
        if ((s.lobe & kLobeDelta) != 0u) {
            s.weight /= 1.0f - mix;
            densityRatio = 1.0f - mix;
        }
        return s;
    }
    // The density of the opaque lobes, as sampleBsdf's (misPdfOfSample adds a rough layer's for MIS;
    // guided vertices have none).
    float bsdfPdf = pdfVertexBsdf(v, s.wi);
    s.pdf = guidedMixturePdf(v, s.wi, bsdfPdf);
    if (bsdfPdf > 0.0f) densityRatio = s.pdf / bsdfPdf;
    if (s.wi.z <= 0.0f || s.pdf <= 0.0f) {
        s.lobe = kLobeNone;
        return s;
    }
    s.weight = evalVertexBsdf(v, s.wi) * s.wi.z / s.pdf;
    return s;
}

// Radiance the vertex reflects towards wo per unit of irradiance, for the roulette's estimate: the
// diffuse part, and a non-delta specular lobe as if it spread its Fresnel reflectance evenly.
vec3 rouletteReflectance(BsdfParams bsdf, vec3 wo) {
    vec3 specular = specularLobeIsDelta(bsdf) ? vec3(0.0f) : specularFresnel(bsdf, wo.z) * (kInvPi * (1.0f - bsdf.transmission));
    return diffuseReflectance(bsdf, wo) + specular;
}
#ifdef GUIDE_LEARN
#include "guiding/guide_learning.glsl"
#endif
#endif

// Russian roulette by the throughput (rouletteSurvival, shared/kernels/path_trace.glsl). The guided
// tracer uses the throughput BSDF sampling would have carried (unguidedScale), as Cycles does with
// its guiding: a direction sent towards bright light has a low throughput because its density is
// high, and its path would otherwise end more often than one sent where little light comes from.
float throughputSurvival(PathState st) {
    return rouletteSurvival(st.depth, max(st.throughput.r, max(st.throughput.g, st.throughput.b)) * st.unguidedScale);
}

// Extends the path by one vertex: emission (MIS-weighted), next-event estimation, BSDF sampling
// and Russian roulette. Returns false when the path has ended.
bool extendPath(inout PathState st) {
    bool useNee = (params.flags & kPathFlagNoDirectLightSampling) == 0u;
    PathVertex v;
    if (!traceVertex(st.ray, v)) {
        // Escaped: the environment light (none when the scene has no environment).
        st.radiance += st.throughput * escapedRadiance(params.lightCount, st.ray.dir, useNee && !st.lastDelta, st.lastPdf,
                                                        st.lastPosition, st.lastNormal);
#ifdef GUIDE_LEARN
        learnSetBase(st.radiance);
#endif
        return false;
    }
    st.throughput *= v.transmittance;

    if (emitsTowards(v.material, v.hit.frontFace)) {
        vec3 le = v.emitted;
        if (le.r + le.g + le.b > 0.0f) {
            float weight = 1.0f;
            if (useNee && !st.lastDelta) weight = emissionMisWeight(v, st.lastPdf, params.lightCount, st.lastPosition, st.lastNormal);
            if (rasterCoversEmission(params.flags, st.depth, st.lastDelta)) weight = 0.0f;
            st.radiance += st.throughput * le * weight;
        }
    }
#ifdef GUIDE_LEARN
    learnSetBase(st.radiance);  // what arrives from here on, the sampled direction brought by further bounces
#endif
    if (st.depth == params.maxDepth) return false;
#ifdef GUIDED
    prepareGuide(v);  // before next-event estimation, whose MIS weight reads the vertex's grid
#endif

    if (useNee) {
        uint skip = rasterCoveredLightTypes(params.flags, st.depth);
        st.radiance += st.throughput * directLight(v, params.lightCount, true, skip, st.rng);
    } else {
        nextSample(st.rng);  // keep the sample dimensions of both modes aligned
        nextSample(st.rng);
        nextSample(st.rng);
    }

    float uLayer = nextSample(st.rng);
    vec3 u = vec3(uLayer, nextSample2(st.rng));  // the direction from one stratified 2-D point
#ifdef GUIDED
    float densityRatio;
    BsdfSample bs = sampleGuided(v, u, densityRatio);
    st.unguidedScale *= densityRatio;
    vec4 irradiance = vertexGuide.irradiance;
#else
    BsdfSample bs = sampleVertexBsdf(v, true, u);
#endif
    float uRoulette = nextSample(st.rng);
    if (bs.lobe == kLobeNone) return false;
    vec3 arriving = st.throughput;
    st.throughput *= bs.weight;
#ifdef GUIDE_LEARN
    learnNoteVertex(v, bs, st.throughput, st.radiance);  // before the roulette, whose survivors' light then counts 1/q
#endif
    st.lastDelta = isDeltaForMis(bs);
    st.lastPdf = st.lastDelta ? bs.pdf : misPdfOfSample(v, bs);
    st.lastPosition = v.hit.position;
    st.lastNormal = v.n;
    spawnRay(v, bs, st.ray);

    // Russian roulette: by the guide's estimate where there is one and --guide-rr is on (guiding.glsl),
    // else by the throughput (throughputSurvival).
    float survive = throughputSurvival(st);
#ifdef GUIDED
    if ((params.flags & kPathFlagGuideRoulette) != 0u && irradiance.w > 0.0f) {
        float expected = luminance(arriving * rouletteReflectance(v.bsdf, v.wo) * irradiance.rgb);
        if (st.reference < 0.0f) st.reference = luminance(st.radiance) + expected;
        survive = guideSurvival(expected, st.reference);
    }
#endif
    if (survive < 1.0f) {
        if (uRoulette >= survive) return false;
        st.throughput /= survive;
    }
    st.depth += 1u;
    return true;
}

// Path regeneration (Novak, Havran, Dachsbacher, "Path Regeneration for Interactive Path
// Tracing", 2010): the loop advances one bounce per iteration and a lane whose path ended starts
// its next sample at once, so lanes running in lock-step (8 per SIMD group on lavapipe) are not
// held idle by the longest path of each sample. Per-sample arithmetic is unchanged.
void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    uint px = pixel % params.width;
    uint py = pixel / params.width;
    uint streamSeed = hashCombine(params.seed, pixel);
    vec4 acc = film[pixel];
    bool addRaster = rasterDirectLightOn(params.flags);
    uint done = 0u;
    uint segments = 0u;
    PathState st = startPath(params.firstSample, streamSeed, px, py);
#ifdef GUIDE_LEARN
    learnBeginPath();
#endif
    while (done < params.sampleCount) {
        segments += 1u;
        if (extendPath(st)) continue;
        vec3 l = st.radiance;
#ifdef GUIDE_LEARN
        learnEndPath(l);
#endif
        if (addRaster) l += rasterDirect[pixel].rgb;
        if (any(isnan(l)) || any(isinf(l))) {
            atomicAdd(counters[kPathTraceCounterNonFinite], 1u);
            l = vec3(0.0f);
        }
        acc += vec4(l, 1.0f);
        done += 1u;
        countTerminations(kTerminationSamples);
        if (done < params.sampleCount) st = startPath(params.firstSample + done, streamSeed, px, py);
    }
    // Samples lavapipe's loop budget cut: the one in flight and those never started.
    countCutItems(kTerminationSamples, params.sampleCount - done);
    film[pixel] = acc;
    if (atomicAdd(counters[kPathTraceCounterSegmentsLow], segments) + segments < segments) atomicAdd(counters[kPathTraceCounterSegmentsHigh], 1u);  // carry
}

#endif
