// Push constants and per-pixel state of the photon integrator's estimate passes (caustics,
// final gather, progressive update), which read the visible points (visible_point.glsl).
#ifndef VKP_PHOTON_RENDER_GLSL
#define VKP_PHOTON_RENDER_GLSL
#include "compat.glsl"
#include "guiding.glsl"
#include "hash.glsl"
#include "photon.glsl"
#include "photon_grid.glsl"
SHARED_BEGIN

// caustic_estimate.comp: L_c = sum f_r dPhi w_cone / ((1 - 2/(3k)) pi r^2) over the caustic map.
struct CausticEstimateParams {
    PhotonGridView grid;
    uint width;
    uint height;
    float radius;         // world units
    float coneK;          // cone filter constant k >= 1 (Jensen 1996)
};
STATIC_ASSERT_SIZE(CausticEstimateParams, 32)

// radiance_photons.comp (Christensen 1999, "Faster photon map global illumination"): about every
// stride-th photon of the global map (radiancePhotonChosen) gets the irradiance its k nearest
// photons estimate, E = sum dPhi / (pi r^2), stored as its power (watts per square metre); final
// gather rays then read the nearest such photon instead of gathering k photons at every hit.
struct RadiancePhotonParams {
    PhotonGridView grid;  // the global map
    uint photonCount;     // photons in the global map
    uint stride;
    uint k;
    float maxRadius;
};
STATIC_ASSERT_SIZE(RadiancePhotonParams, 32)

// Whether a photon of the global map is one of the ~1/stride that become radiance photons (besides
// the first photon of every bucket and every photon of a bucket holding fewer than stride): a hash
// of the photon's own record, not its place in the grid. So a photon keeps its choice (and, with
// the same k nearest, its irradiance) whatever photons arrive or leave elsewhere in the map: an
// animation's frames that change a few photon paths change the radiance photons only near them.
// ("Every stride-th in grid order" shifted the choice over the whole map whenever one photon was
// added or removed, and the whole image flickered between frames; docs/benchmarks.md.)
INLINE bool radiancePhotonChosen(GpuPhoton p, uint stride) {
    uint h = hashCombine(hashCombine(pcgHash(p.direction), p.normal), p.powerRG);
    h = hashCombine(hashCombine(h, p.powerBFlags), p.lightIndex);
    return h % stride == 0u;
}

// final_gather.comp: one dispatch per gather ray (rayIndex of gatherRays) adds
// (1 / gatherRays) f cos / pdf * L_global(y) at the visible point; gatherRays = 0 reads the global
// map at the visible point itself instead (non-primary, non-caustic photons).
struct FinalGatherParams {
    PhotonGridView grid;
    uint width;
    uint height;
    uint sampleIndex;     // the visible points' camera sample index
    uint seed;
    uint gatherRays;
    uint rayIndex;
    uint k;               // nearest photons per estimate (<= kMaxGatherK)
    float maxRadius;      // world units
    uint maxSpecularDepth;
    uint radianceLookup;  // 1: the grid holds radiance photons (read the nearest one), 0: photons
    float lookupRadius;   // radiance photons farther than this are not used
    uint reuse;           // 1: a visible point whose BSDF is rough (gatherReusable) leaves its ray in
                          // the gather-sample buffer for gather_reuse.comp instead of adding it to the film
    // Gather directions importance-sampled from the photons (the guiding cache's grids: their
    // incoming flux) with probability guide.mix, else the BSDF's, weighted by the mixture density
    // (one-sample MIS); guide.mix 0: the BSDF's alone.
    GuideParams guide;
    // Gather rays a pixel takes in the whole render (samples x gatherRays; 0: not known, past 2^30):
    // the size of the sampler's per-pixel permutation (makePixelSampler), so that every dimension
    // of a pixel's gather rays is stratified on its own and the dimensions are not correlated.
    uint samplerCount;
    uint pad1;
    uint pad2;
    uint pad3;
};
STATIC_ASSERT_SIZE(FinalGatherParams, 112)

// One final-gather ray of one pixel, kept for gather_reuse.comp: its direction (world, octahedral)
// and the radiance it brought back over the density that chose it, L / pdf. A negative x marks a
// pixel whose rays are not shared (its BSDF is not gatherReusable; the ray went to the film);
// zero, a ray that found nothing (or no direction): a sample of value zero that still counts.
struct GatherSample {
    vec3 radianceOverPdf;
    uint direction;
};
STATIC_ASSERT_SIZE(GatherSample, 16)

// gather_reuse.comp (docs/photon-mapping.md, "Gathers shared between pixels"): each pixel whose
// BSDF is rough adds the mean of f_p(wi_q) cos / pdf_q * L_q over the gather rays of the pixels q
// around it (its own included) that lie on the same surface: within `radius` pixel footprints in
// world space, normals within kGatherReuseCos, off its plane by at most a tenth of that.
struct GatherReuseParams {
    uint width;
    uint height;
    uint gatherRays;      // rays per pixel in the gather-sample buffer (ray r of pixel p: r * pixels + p)
    uint window;          // neighbours searched: (2 window + 1)^2 pixels, window = ceil(radius)
    float radius;         // in pixel footprints (0: the pixel's own rays only)
    float footprintScale; // the visible point's cone width times this is its pixel's footprint
    uint pad0;
    uint pad1;
};
STATIC_ASSERT_SIZE(GatherReuseParams, 32)

const uint kMaxGatherReuseWindow = 8u;
// Normals of pixels that share their gathers at most ~26 degrees apart.
const float kGatherReuseCos = 0.9f;

// sppm_update.comp: stochastic progressive photon mapping (Hachisuka & Jensen 2009), one update
// of every pixel's statistics per photon pass.
struct SppmParams {
    PhotonGridView grid;
    uint width;
    uint height;
    float alpha;          // fraction of new photons kept (eq. 6), 0 < alpha < 1
    uint pad0;
};
STATIC_ASSERT_SIZE(SppmParams, 32)

// Per pixel: accumulated flux tau (watts, weighted by the camera path's throughput), the photon
// count N and the squared radius R^2 (eq. 5-7).
struct SppmPixel {
    vec3 flux;
    float photons;
    float radius2;
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(SppmPixel, 32)

// x where finite, else 0 (NaN fails the comparison).
INLINE float finiteOrZero(float x) { return abs(x) <= 3.40282347e38f ? x : 0.0f; }

// A pixel's progressive radiance estimate after `passes` photon passes (eq. 8 with N_e = passes
// emitted batches): tau / (passes * pi * R^2); 0 where it is not finite (no radius yet). The
// host's image (ProgressivePhotonIntegrator::finish) and the viewer's display kernel both use it.
INLINE vec3 sppmRadiance(SppmPixel px, float passes) {
    vec3 l = px.flux / (passes * kPi * px.radius2);
    return vec3(finiteOrZero(l.x), finiteOrZero(l.y), finiteOrZero(l.z));
}

SHARED_END
#endif
