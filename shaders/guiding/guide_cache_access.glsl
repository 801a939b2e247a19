// Reading the guiding cache (guide_cache_build.comp) at a surface point: the grid of the point's
// cache cell and normal bin, a CDF over the bin axis's hemisphere (shared/guiding.glsl). Shared by
// the guided path tracer and the photon integrator's final gather. The includer defines
// GUIDE_CACHE_CELLS_BINDING and GUIDE_CACHE_CDFS_BINDING.
#ifndef VKP_GUIDE_CACHE_ACCESS_GLSL
#define VKP_GUIDE_CACHE_ACCESS_GLSL

#include "shared/guiding.glsl"
#include "shared/normal_bins.glsl"
#include "shared/photon_grid.glsl"
#include "shared/sampling.glsl"

layout(std430, set = 0, binding = GUIDE_CACHE_CELLS_BINDING) readonly buffer CacheCells { ivec4 cacheCells[]; };
layout(std430, set = 0, binding = GUIDE_CACHE_CDFS_BINDING) readonly buffer CacheCdfs { float cacheCdfs[]; };

// A cached grid covers its normal bin axis's hemisphere; at a point whose shading normal is not
// that axis, the directions of the surface's hemisphere outside it have no grid density, and only
// the BSDF half of the mixture reaches them: at least this share stays the BSDF's there, so that
// a mixture of 1 (no BSDF half) does not lose their light (inside a curved furnace: about 3 % of it).
const float kCachedGuideMaxMix = 0.9f;

struct CachedGuide {
    bool found;   // the point's cell has a grid (else: sample the BSDF)
    uint bucket;  // the cell's bucket in the cache
    uint bin;     // the normal bin
    vec3 t;       // the grid's frame: the bin axis and a basis around it
    vec3 b;
    vec3 n;
};

// The cache's grid at `position` for shading normal `normal` (grid: the cache's cells).
CachedGuide findCachedGuide(PhotonGridView grid, vec3 position, vec3 normal) {
    CachedGuide g;
    g.found = false;
    g.bucket = 0u;
    g.bin = 0u;
    g.t = vec3(1.0f, 0.0f, 0.0f);
    g.b = vec3(0.0f, 1.0f, 0.0f);
    g.n = vec3(0.0f, 0.0f, 1.0f);
    ivec3 cell = gridCell(position, grid.invCellSize);
    uint bucket = gridHash(cell, grid.tableMask);
    ivec4 cached = cacheCells[bucket];
    if (cached.w == 0 || ivec3(cached.x, cached.y, cached.z) != cell) return g;
    g.found = true;
    g.bucket = bucket;
    g.bin = normalBin(normal);
    g.n = normalBinAxis(g.bin);
    orthonormalBasis(g.n, g.t, g.b);
    return g;
}

// The probability of sampling the grid at a point of shading normal `normal` for the mixture
// probability `mix`: less where the normal is not the bin's axis (kCachedGuideMaxMix).
float cachedGuideMix(CachedGuide g, vec3 normal, float mix) {
    return dot(g.n, normal) < 0.99999f ? min(mix, kCachedGuideMaxMix) : mix;
}

// Where the grid's CDF (kMaxGuideCells entries) starts in cacheCdfs.
uint cachedGuideCdfBase(CachedGuide g) { return (g.bucket * kNormalBins + g.bin) * kMaxGuideCells; }

// guidePdf and guideSample (shared/guiding.glsl) over a cached grid, read in place.
#define GUIDE_CACHE_AT(i) cacheCdfs[cdfBase + (i)]
float cachedGuidePdf(uint cdfBase, uint m, uint n, vec3 wi) {
    if (wi.z <= 0.0f) return 0.0f;
    uint c = guideDirectionCell(wi, m, n);
    return guideDensity(GUIDE_CELL_PROBABILITY(GUIDE_CACHE_AT, c), m, n, wi);
}
vec3 cachedGuideSample(uint cdfBase, uint m, uint n, vec2 u) {
    vec3 wi;
    GUIDE_SAMPLE(GUIDE_CACHE_AT, m, n, u, wi)
    return wi;
}
#undef GUIDE_CACHE_AT

#endif
