// The photon hash grid (counting sort of photons by hashed cell): cell coordinates, the hash into
// a power-of-two table, which photons a map keeps, and the push constants of the build kernels.
// Shared by the grid build (grid_*.comp), the gathers (photon_gather.glsl) and the host tests.
#ifndef VKP_PHOTON_GRID_GLSL
#define VKP_PHOTON_GRID_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

// Most photons a k-nearest gather returns (photon_gather.glsl keeps them in a local heap).
const uint kMaxGatherK = 64u;
// A photon counts at a query point when its surface normal is within 60 degrees of the query's
// normal: photons on a surface facing away (the other side of a thin wall) are rejected.
const float kGatherNormalCosine = 0.5f;

// Cell coordinates are clamped so that positions far outside the scene cannot overflow int.
const float kGridMaxCell = 1.0e9f;

// Integer cell of a world-space position for cells of size 1 / invCellSize.
INLINE ivec3 gridCell(vec3 p, float invCellSize) {
    vec3 c = clamp(floor(p * invCellSize), vec3(-kGridMaxCell), vec3(kGridMaxCell));
    return ivec3(int(c.x), int(c.y), int(c.z));
}

// Teschner et al. 2003 spatial hash (large primes, xor), masked to the power-of-two table.
INLINE uint gridHash(ivec3 c, uint tableMask) {
    return ((uint(c.x) * 73856093u) ^ (uint(c.y) * 19349663u) ^ (uint(c.z) * 83492791u)) & tableMask;
}

// A map keeps the valid photons that carry every `required` flag and none of the `rejected`.
INLINE bool photonSelected(uint flags, uint required, uint rejected) {
    return (flags & 1u) != 0u && (flags & required) == required && (flags & rejected) == 0u;
}

// Push constants of grid_count.comp, grid_scatter.comp and grid_sort_cells.comp.
struct PhotonGridParams {
    float invCellSize;
    uint tableMask;       // table size - 1 (a power of two)
    uint slotCount;       // photon slots in the input buffer (empty slots are skipped)
    uint requiredFlags;
    uint rejectedFlags;
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(PhotonGridParams, 32)

// How a gather shader finds a grid: the first three fields of every estimate's push constants.
struct PhotonGridView {
    float invCellSize;
    uint tableMask;
    float photonPower;    // watts carried by a photon of relative power 1 in this map
    uint pad0;
};
STATIC_ASSERT_SIZE(PhotonGridView, 16)

// Push constants of the compaction kernels (compact_*.comp).
struct PhotonCompactParams {
    uint slotCount;       // slots in the chunk
    uint scannedCount;    // entries of the rank scan before its total (>= slotCount)
    uint capacity;        // photons the dense map can hold
    uint requiredFlags;
    uint rejectedFlags;
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(PhotonCompactParams, 32)

SHARED_END
#endif
