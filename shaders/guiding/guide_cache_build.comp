// The guiding cache (--guide-cache on): one invocation per (bucket, normal bin) of a coarse grid
// over the guiding photons builds the Jensen grid of the photons in the bucket's owner cell whose
// normals fall in the bin, in the bin axis's frame, weighted by flux (the BRDF is left out: exact
// for diffuse surfaces, and the BSDF half of the mixture covers glossy ones), and stores its CDF.
// Direct photons are left out. The bucket's cell is stored so lookups can tell it from other
// cells hashed to the same bucket: of the cells in the bucket, the least (x, then y, then z).
// The cache's grid leaves its buckets unsorted (a sort per bucket passes lavapipe's loop budget in
// cells of hundreds to thousands of photons), so nothing here may depend on the photons' order:
// the owner cell is a minimum and the sums are fixed-point integers (kCacheFixedPoint units of
// relative power), which add up the same in any order. For guide-driven Russian roulette it also
// stores the grid's indirect irradiance: the photons' flux over the area they cover in the bin's
// plane (their bounding rectangle, each side widened by the range's expected shortfall for that
// many uniform points, (count + 1) / (count - 1), and kept between a quarter and the whole cell
// edge), and the photon count, from which lookups recompute the grid's resolution under
// --guide-adapt.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/guide_cache.glsl"
#include "shared/guiding.glsl"
#include "shared/photon.glsl"
#include "common/termination_counters.glsl"

layout(local_size_x = kGuideCacheGroupSize) in;

layout(std430, set = 0, binding = kGuideCacheCellStartBinding) readonly buffer CellStart { uint cellStart[]; };
#include "common/segmented_arrays.glsl"
SEGMENTED_ARRAY(kGuideCachePhotonBinding, GridPhotons, gridPhotonTable);
layout(std430, set = 0, binding = kGuideCacheCellsBinding) writeonly buffer CacheCells { ivec4 cacheCells[]; };  // xyz cell, w 1: used
layout(std430, set = 0, binding = kGuideCacheCdfsBinding) writeonly buffer CacheCdfs { float cacheCdfs[]; };    // kMaxGuideCells each
layout(std430, set = 0, binding = kGuideCacheIrradianceBinding) writeonly buffer CacheIrradiance { vec4 cacheIrradiance[]; };  // rgb W/m^2, w photons

layout(push_constant) uniform Push { GuideParams guide; };

const float kCacheFixedPoint = 4096.0f;  // 1/4096 of a photon's relative power: sums to 2^20 photons

bool cellBefore(ivec3 a, ivec3 b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

uint fixedPoint(float relativePower) { return uint(max(relativePower, 0.0f) * kCacheFixedPoint + 0.5f); }

void buildCacheCell() {
    uint index = gl_GlobalInvocationID.x;
    uint bucket = index / kNormalBins;
    uint bin = index - bucket * kNormalBins;
    if (bucket > guide.grid.tableMask) return;
    uint gm = guide.gridSize & 0xffu;
    uint gn = (guide.gridSize >> 8u) & 0xffu;
    uint begin = cellStart[bucket];
    uint end = cellStart[bucket + 1u];
    uint visited = 0u;  // fewer than the cell holds twice when lavapipe's loop budget cut a loop
    ivec3 cell = ivec3(0);
    for (uint i = begin; i < end; ++i) {
        visited += 1u;
        ivec3 c = gridCell(PHOTON_AT(gridPhotonTable, i).position, guide.grid.invCellSize);
        if (i == begin || cellBefore(c, cell)) cell = c;
    }
    if (bin == 0u) cacheCells[bucket] = ivec4(cell, begin < end ? 1 : 0);

    uint sums[kMaxGuideCells];
    for (uint i = 0u; i < kMaxGuideCells; ++i) sums[i] = 0u;
    vec3 axis = normalBinAxis(bin);
    vec3 t;
    vec3 b;
    orthonormalBasis(axis, t, b);
    uvec3 fluxSum = uvec3(0u);
    float count = 0.0f;
    vec2 lo = vec2(kInfinity);
    vec2 hi = vec2(-kInfinity);
    for (uint i = begin; i < end; ++i) {
        visited += 1u;
        GpuPhoton p = PHOTON_AT(gridPhotonTable, i);
        if ((photonFlags(p) & kPhotonPrimary) != 0u || gridCell(p.position, guide.grid.invCellSize) != cell ||
            normalBin(decodeOctahedral(p.normal)) != bin)
            continue;
        vec3 wi = toLocal(decodeOctahedral(p.direction), t, b, axis);
        vec3 power = photonRelativePower(p);
        if (wi.z > 0.0f) sums[guideDirectionCell(wi, gm, gn)] += fixedPoint(luminance(power));
        fluxSum += uvec3(fixedPoint(power.r), fixedPoint(power.g), fixedPoint(power.b));
        count += 1.0f;
        vec2 st = vec2(dot(p.position, t), dot(p.position, b));
        lo = min(lo, st);
        hi = max(hi, st);
    }
    noteLoopCut(visited, 2u * (max(end, begin) - begin));
    float cells[kMaxGuideCells];
    for (uint i = 0u; i < kMaxGuideCells; ++i) cells[i] = float(sums[i]) / kCacheFixedPoint;
    vec3 flux = vec3(fluxSum) / kCacheFixedPoint;
    uint photonsPerCell = guide.gridSize >> 16u;
    uvec2 size = photonsPerCell > 0u ? guideAdaptiveSize(gm, gn, photonsPerCell, count) : uvec2(gm, gn);
    guideCoarsen(cells, gm, gn, size.x, size.y);
    guideFinalize(cells, size.x, size.y);
    for (uint i = 0u; i < kMaxGuideCells; ++i) cacheCdfs[index * kMaxGuideCells + i] = cells[i];
    float edge = 1.0f / guide.grid.invCellSize;
    vec2 extent = count > 0.0f ? (hi - lo) * ((count + 1.0f) / max(count - 1.0f, 1.0f)) : vec2(edge);
    extent = clamp(extent, vec2(0.25f * edge), vec2(edge));
    cacheIrradiance[index] = vec4(flux * (guide.grid.photonPower / (extent.x * extent.y)), count);
}

void main() {
    buildCacheCell();
    countTerminations(kTerminationGridCells);  // rays and gathers this invocation's bounds cut short
}
