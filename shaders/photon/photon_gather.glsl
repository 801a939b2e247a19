// GLSL-only gathers over a photon hash grid (host/photon/photon_grid.h): fixed-radius sums with
// an optional cone filter, and the k nearest photons with a radius that shrinks as the search
// finds them (a max-heap of the k best). Both visit the cells that overlap the query's cube,
// skip photons of other cells that share a bucket, and apply the normal test (photons stored on
// surfaces facing away, e.g. the other side of a wall, are not counted).
//
// Include after scene_access.glsl (or at least shared/bsdf.glsl, shared/sampling.glsl) with
// PHOTON_GRID_BINDING defined: the grid's cell starts and photons are bound at that binding and
// the next.
#ifndef VKP_PHOTON_GATHER_GLSL
#define VKP_PHOTON_GATHER_GLSL

#include "shared/photon.glsl"
#include "shared/photon_estimate.glsl"
#include "shared/photon_grid.glsl"
#include "shared/termination_record.glsl"
#include "common/segmented_arrays.glsl"

#ifndef PHOTON_GRID_BINDING
#error "define PHOTON_GRID_BINDING before including photon_gather.glsl"
#endif

layout(std430, set = 0, binding = PHOTON_GRID_BINDING) readonly buffer GridCellStart { uint gridCellStart[]; };
// The grid's photons: a segmented array (segmented.glsl), so a map may outgrow one buffer.
SEGMENTED_ARRAY(PHOTON_GRID_BINDING + 1, GridPhotons, gridPhotonTable);

// The grid's i-th photon (bucket order).
GpuPhoton gridPhoton(uint i) { return PHOTON_AT(gridPhotonTable, i); }

// Queries visit at most this many cells per axis (a radius far above the cell size is clamped).
const int kMaxGatherCellsPerAxis = 8;
// k-nearest queries visit rings of cells up to this Chebyshev distance from the query's cell.
const int kMaxGatherRings = 3;

void gatherCellRange(PhotonGridView g, vec3 x, float r, out ivec3 lo, out ivec3 hi) {
    lo = gridCell(x - vec3(r), g.invCellSize);
    hi = gridCell(x + vec3(r), g.invCellSize);
    hi = min(hi, lo + ivec3(kMaxGatherCellsPerAxis - 1));
}

// Squared distance from x to the cell's box (0 inside).
float cellDistance2(PhotonGridView g, ivec3 c, vec3 x) {
    float size = 1.0f / g.invCellSize;
    vec3 lo = vec3(c) * size;
    vec3 d = max(max(lo - x, x - (lo + vec3(size))), vec3(0.0f));
    return dot(d, d);
}

bool photonCounts(GpuPhoton p, vec3 n, uint required, uint rejected) {
    return photonSelected(photonFlags(p), required, rejected) &&
           dot(decodeOctahedral(p.normal), n) > kGatherNormalCosine;
}

// Sum over the photons within r of x: f_r(wo, wi_p) * relative power * cone weight (coneK <= 0:
// no filter, weight 1). wo and the frame (t, b, n) are those of the query's surface, wo local.
struct FixedRadiusGather {
    vec3 weightedPower;
    uint count;
};

// `lambertian` (a constant at each call: gatherFixedRadius) gives the photon loop a copy without
// evalBsdf's other lobes (evalBsdfAs; a dense caustic's thousands of photons paid them each).
FixedRadiusGather gatherFixedRadiusWith(PhotonGridView g, vec3 x, float r, float coneK, uint required, uint rejected,
                                        BsdfParams bsdf, vec3 wo, vec3 t, vec3 b, vec3 n, const bool lambertian) {
    BsdfWoTerms woTerms = bsdfWoTerms(bsdf, wo);
    FixedRadiusGather result;
    result.weightedPower = vec3(0.0f);
    result.count = 0u;
    float r2 = r * r;
    ivec3 lo;
    ivec3 hi;
    gatherCellRange(g, x, r, lo, hi);
    uint cells = 0u;  // cells and photons visited: fewer than the ranges hold when a loop was cut
    for (int cz = lo.z; cz <= hi.z; ++cz)
        for (int cy = lo.y; cy <= hi.y; ++cy)
            for (int cx = lo.x; cx <= hi.x; ++cx) {
                cells += 1u;
                ivec3 c = ivec3(cx, cy, cz);
                if (cellDistance2(g, c, x) > r2) continue;
                uint bucket = gridHash(c, g.tableMask);
                uint begin = gridCellStart[bucket];
                uint end = gridCellStart[bucket + 1u];
                uint visited = 0u;
                for (uint i = begin; i < end; ++i) {
                    visited += 1u;
                    GpuPhoton p = gridPhoton(i);
                    vec3 d = p.position - x;
                    float d2 = dot(d, d);
                    if (d2 > r2 || gridCell(p.position, g.invCellSize) != c) continue;
                    if (!photonCounts(p, n, required, rejected)) continue;
                    vec3 wi = toLocal(decodeOctahedral(p.direction), t, b, n);
                    float w = coneK > 0.0f ? coneFilterWeight(sqrt(d2), r, coneK) : 1.0f;
                    result.weightedPower += evalBsdfAs(bsdf, woTerms, wo, wi, lambertian) * photonRelativePower(p) * w;
                    result.count += 1u;
                }
                noteLoopCut(visited, max(end, begin) - begin);
            }
    ivec3 extent = max(hi - lo + ivec3(1), ivec3(0));
    noteLoopCut(cells, uint(extent.x * extent.y * extent.z));
    return result;
}

FixedRadiusGather gatherFixedRadius(PhotonGridView g, vec3 x, float r, float coneK, uint required, uint rejected,
                                    BsdfParams bsdf, vec3 wo, vec3 t, vec3 b, vec3 n) {
    return bsdfIsLambertian(bsdf)
               ? gatherFixedRadiusWith(g, x, r, coneK, required, rejected, bsdf, wo, t, b, n, true)
               : gatherFixedRadiusWith(g, x, r, coneK, required, rejected, bsdf, wo, t, b, n, false);
}

// The k-nearest search's max-heap on squared distance (heapDistance2[0] the farthest), private
// to the invocation. Kept at global scope: passed as function arguments, arrays are copied.
float heapDistance2[kMaxGatherK];
uint heapIndex[kMaxGatherK];

// Adds an entry to a heap holding `size` entries (size < capacity): sift up from the new leaf.
void heapPush(uint size, float d2, uint index) {
    uint hole = size;
    while (hole > 0u && heapDistance2[(hole - 1u) / 2u] < d2) {
        uint parent = (hole - 1u) / 2u;
        heapDistance2[hole] = heapDistance2[parent];
        heapIndex[hole] = heapIndex[parent];
        hole = parent;
    }
    heapDistance2[hole] = d2;
    heapIndex[hole] = index;
}

// Replaces the farthest entry (the root) of a full heap of `size` entries: sift down.
void heapReplaceRoot(uint size, float d2, uint index) {
    uint hole = 0u;
    uint child = 1u;
    while (child < size) {
        if (child + 1u < size && heapDistance2[child + 1u] > heapDistance2[child]) child += 1u;
        if (heapDistance2[child] <= d2) break;
        heapDistance2[hole] = heapDistance2[child];
        heapIndex[hole] = heapIndex[child];
        hole = child;
        child = 2u * hole + 1u;
    }
    heapDistance2[hole] = d2;
    heapIndex[hole] = index;
}

// State of a k-nearest search: entries in the heap, its capacity k, the search radius squared.
struct NearestSearch {
    uint count;
    uint capacity;
    float radius2;
};

// Offers the photons of cell c to the heap of a k-nearest search. `one` (a constant at each call)
// is a search for the nearest photon alone (k = 1): it keeps that photon without the heap's loops,
// which lavapipe runs under a lane mask for every photon a cell holds.
void gatherNearestInCell(PhotonGridView g, ivec3 c, vec3 x, vec3 n, uint required, uint rejected,
                         inout NearestSearch s, const bool one) {
    uint bucket = gridHash(c, g.tableMask);
    uint begin = gridCellStart[bucket];
    uint end = gridCellStart[bucket + 1u];
    uint visited = 0u;  // fewer than the cell holds when the loop was cut
    for (uint i = begin; i < end; ++i) {
        visited += 1u;
        GpuPhoton p = gridPhoton(i);
        vec3 d = p.position - x;
        float d2 = dot(d, d);
        if (d2 < s.radius2 && gridCell(p.position, g.invCellSize) == c && photonCounts(p, n, required, rejected)) {
            if (one) {
                heapDistance2[0] = d2;
                heapIndex[0] = i;
                s.count = 1u;
                s.radius2 = d2;
            } else if (s.count < s.capacity) {
                heapPush(s.count, d2, i);
                s.count += 1u;
            } else {
                heapReplaceRoot(s.capacity, d2, i);
            }
            if (s.count == s.capacity) s.radius2 = heapDistance2[0];  // shrinks to the k-th distance
        }
    }
    noteLoopCut(visited, max(end, begin) - begin);
}

// The k nearest photons (k <= kMaxGatherK) within maxRadius of x: fills heapIndex[0, found) with
// grid indices and returns found. radius2 is the squared distance of the farthest one when k
// were found, else maxRadius^2 (the disk the estimate divides by).
uint gatherNearestWith(PhotonGridView g, vec3 x, vec3 n, uint k, float maxRadius, uint required, uint rejected,
                       out float radius2, const bool one) {
    NearestSearch s;
    s.count = 0u;
    s.capacity = one ? 1u : clamp(k, 1u, kMaxGatherK);
    s.radius2 = maxRadius * maxRadius;
    // Cells in rings of growing Chebyshev distance around x's cell: once k photons are found the
    // radius shrinks to the k-th distance and the outer rings' cells are mostly skipped.
    ivec3 center = gridCell(x, g.invCellSize);
    int rings = min(int(ceil(maxRadius * g.invCellSize)), kMaxGatherRings);
    uint ringsDone = 0u;  // fewer than rings + 1 when the loop was cut
    for (int ring = 0; ring <= rings; ++ring, ++ringsDone)
        for (int dz = -ring; dz <= ring; ++dz)
            for (int dy = -ring; dy <= ring; ++dy)
                for (int dx = -ring; dx <= ring; ++dx) {
                    ivec3 c = center + ivec3(dx, dy, dz);
                    if (max(abs(dx), max(abs(dy), abs(dz))) == ring && cellDistance2(g, c, x) <= s.radius2)
                        gatherNearestInCell(g, c, x, n, required, rejected, s, one);
                }
    noteLoopCut(ringsDone, uint(max(rings + 1, 0)));
    radius2 = s.count == s.capacity ? heapDistance2[0] : maxRadius * maxRadius;
    return s.count;
}

uint gatherNearest(PhotonGridView g, vec3 x, vec3 n, uint k, float maxRadius, uint required, uint rejected,
                   out float radius2) {
    return gatherNearestWith(g, x, n, k, maxRadius, required, rejected, radius2, false);
}

// The nearest photon alone (heapIndex[0] when found): gatherNearest with k = 1, without the heap.
bool findNearest(PhotonGridView g, vec3 x, vec3 n, float maxRadius, uint required, uint rejected) {
    float radius2;
    return gatherNearestWith(g, x, n, 1u, maxRadius, required, rejected, radius2, true) != 0u;
}

// Reflected radiance estimate from the k nearest photons (Jensen: L = sum f_r dPhi / (pi r^2),
// scaled by (k - 1) / k to remove the k-nearest estimate's bias: nearestEstimateScale), in watts
// through g.photonPower. wo local in the frame (t, b, n).
vec3 radianceNearest(PhotonGridView g, vec3 x, uint k, float maxRadius, uint required, uint rejected,
                     BsdfParams bsdf, vec3 wo, vec3 t, vec3 b, vec3 n) {
    float radius2;
    uint found = gatherNearest(g, x, n, k, maxRadius, required, rejected, radius2);
    BsdfWoTerms woTerms = bsdfWoTerms(bsdf, wo);
    vec3 sum = vec3(0.0f);
    for (uint j = 0u; j < found; ++j) {
        GpuPhoton p = gridPhoton(heapIndex[j]);
        vec3 wi = toLocal(decodeOctahedral(p.direction), t, b, n);
        sum += evalBsdfWith(bsdf, woTerms, wo, wi) * photonRelativePower(p);
    }
    return sum * (g.photonPower * nearestEstimateScale(found, clamp(k, 1u, kMaxGatherK)) / (kPi * radius2));
}

#endif
