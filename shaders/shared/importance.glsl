// Importance-driven photon deposition (docs/importance-deposition.md): importons shot from the
// camera, the deposition probability of Keller & Wald (2000, shared/papers/000) and the density
// control of Suykens & Willems (2000, shared/papers/002). Shared by importon_trace.comp,
// importance_lookup.comp, photon_deposit.comp and the host.
#ifndef VKP_IMPORTANCE_GLSL
#define VKP_IMPORTANCE_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "gpu_types.glsl"
#include "hash.glsl"
#include "photon.glsl"
#include "photon_grid.glsl"
SHARED_BEGIN

// How photons are kept at deposition (--deposit).
const uint kDepositAll = 0u;         // every photon (Jensen's photon map)
const uint kDepositImportance = 1u;  // kept with p = min(1, f * importance density) (Keller & Wald)
const uint kDepositDensity = 2u;     // kept by the ratio of current to required density (Suykens & Willems)

const uint kImportonValid = 1u;    // the slot holds an importon (slots of paths that ended early stay 0)
const uint kImportonPrimary = 2u;  // the first importon of its path: what the camera sees directly
                                   // (or through mirror-like bounces); the test rays of f

// One stored importon (importon_trace.comp; read by importance_splat.comp, importon_importance.comp
// and the host).
struct GpuImporton {
    vec3 position;          // world space
    float importance;       // visual importance W: the luminance of the camera path's throughput
                            // (every importon path carries 1)
    float pathImportance;   // Suykens & Willems eq. 4 for a path eye -> y -> x: f_r(y) cos(y) cos(x)
                            // / |x - y|^2 times the albedo of earlier bounces; 0 without a y
    uint normal;            // octahedral unit vector (16+16 bits): the shading normal on the side
                            // the camera path arrived from (the importance grid's normal bin)
    uint flags;             // kImportonValid | kImportonPrimary
    uint pad0;
};
STATIC_ASSERT_SIZE(GpuImporton, 32)

// Importance values are rounded to half precision, as when importons were GpuPhoton records with
// them in the half-float power channels: the importance grid, and so deposition, stay as they
// were measured (docs/importance-deposition.md). Values must be at most kMaxHalfFloat.
INLINE float roundToHalf(float x) {
    return unpackHalf2x16(packHalf2x16(vec2(x, 0.0f))).x;
}

INLINE GpuImporton makeImporton(vec3 position, float importance, float pathImportance, vec3 normal, uint flags) {
    GpuImporton i;
    i.position = position;
    i.importance = roundToHalf(importance);
    i.pathImportance = roundToHalf(pathImportance);
    i.normal = encodeOctahedral(normal);
    i.flags = flags;
    i.pad0 = 0u;
    return i;
}

// Push constants of importon_trace.comp.
struct ImportonTraceParams {
    GpuCamera camera;
    uint width;              // the image the camera samples (its aspect ratio)
    uint height;
    uint firstPath;          // Halton index of the first importon path
    uint pathCount;
    uint maxDeposits;        // importons stored per path at most: slot = path * maxDeposits + k
    uint seed;
    uint maxDepth;           // bounces followed per path (delta and non-delta together)
    uint pad0;
};
STATIC_ASSERT_SIZE(ImportonTraceParams, 96)

// The importance grid: importons summed into hashed cells at kImportanceLevels cell sizes (each
// twice the last) and six normal bins, so a photon finds the importance around it with one
// lookup per level: the finest cell holding at least k importons (Keller & Wald's n nearest)
// gives the importance density, its sum over the cell's size squared (a surface crossing a cell
// of size h covers about h^2). Sparse regions read a coarse level; no level's search grows
// with the importons around the photon. Open addressing with 32-bit keys; integer sums, so the
// table does not depend on the order the importons arrive in.
const uint kImportanceLevels = 8u;
const uint kPathImportanceLevels = 6u;        // path importance is read from the finest levels only
const uint kImportanceEmptyKey = 0u;         // a zero-filled table is empty
const uint kImportanceMaxProbes = 64u;
const float kImportanceFixedPoint = 1024.0f;  // importance units per integer step
const float kMaxImportonImportance = 64.0f;   // W clamped to it (sums stay within 32 bits)

struct ImportanceCell {
    uint key;                // kImportanceEmptyKey while free
    uint count;              // importons in the cell
    uint importance;         // sum of W * kImportanceFixedPoint
    uint maxPathImportance;  // float bits of the largest path importance (positive: ordered as uints)
};
STATIC_ASSERT_SIZE(ImportanceCell, 16)

// Push constants of importance_splat.comp and importance_lookup.comp.
struct ImportanceGridParams {
    float invCellSize;       // of level 0
    uint tableMask;          // table size - 1 (a power of two)
    uint slotCount;          // slots of the input (importons, or photons)
    uint k;                  // importons a cell needs before its level is used
    uint requiredFlags;      // lookup: only the photons the map keeps (photonSelected)
    uint rejectedFlags;
    uint pad0;
    uint pad1;
};
STATIC_ASSERT_SIZE(ImportanceGridParams, 32)

INLINE uint importanceSlotHash(ivec3 c, uint level, uint bin) {
    return hashCombine(hashCombine(hashCombine(hashCombine(level * 8u + bin, uint(c.x)), uint(c.y)), uint(c.z)),
                       0x494d5047u);
}

// The key stored for a cell: a second, independent hash (never the empty key).
INLINE uint importanceKey(ivec3 c, uint level, uint bin) {
    uint key = pcgHash(uint(c.x) * 73856093u ^ uint(c.y) * 19349663u ^ uint(c.z) * 83492791u ^ (level * 8u + bin) * 2654435761u);
    return key == kImportanceEmptyKey ? 1u : key;
}

INLINE ivec3 importanceCell(vec3 x, float invCellSize, uint level) {
    return gridCell(x, invCellSize / float(1u << level));
}

// Push constants of photon_deposit.comp.
struct PhotonDepositParams {
    PhotonGridView map;      // the map's own grid (density control: photons stored in earlier rounds)
    uint slotCount;
    uint firstPath;          // Halton index of the chunk's first path (slot / maxDeposits + firstPath)
    uint maxDeposits;
    uint seed;
    uint mode;               // kDeposit*
    uint round;              // density control: 0 before anything is stored (no grid to read)
    uint densityK;           // nearest stored photons per current-density estimate
    uint cutoff;             // 1: drop photons with p < epsilon (biased); 0: clamp p to epsilon
    uint requiredFlags;      // photons the map does not keep are left alone (photonSelected)
    uint rejectedFlags;
    float importanceScale;   // f: p = min(1, f * importance density)
    float epsilon;           // floor of p
    float densityAccuracy;   // C: required density = C * path importance (photons per square unit)
    float minDensity;        // required density where the path importance is lower
    float densityRadius;     // search radius of the current-density estimate
    float densityFloor;      // least acceptance where some density is required (bounds the weight 1/p)
    uint redistribute;       // density control: 1 spreads a rejected photon's power over its nearest
                             // stored neighbours (Suykens & Willems); 0: Russian-roulette weighting
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(PhotonDepositParams, 96)

// Redistributed power is summed in fixed point per grid photon and channel (integer atomics:
// the same sums whatever the order).
const float kRedistributedFixedPoint = 4096.0f;  // steps per unit of relative power

// Push constants of deposit_redistribute.comp.
struct RedistributeParams {
    uint gridPhotons;        // photons in the map's grid (stored by the earlier rounds)
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(RedistributeParams, 16)

// Keller & Wald's deposition probability from the importance density sensed at the photon.
INLINE float importanceAcceptance(float importanceDensity, float importanceScale) {
    return min(1.0f, importanceScale * importanceDensity);
}

// Suykens & Willems' acceptance from the ratio of current to required density: a translated
// cosine, 1 up to half the required density, 0 from one and a half times it.
INLINE float densityAcceptance(float currentDensity, float requiredDensity) {
    if (!(requiredDensity > 0.0f)) return 0.0f;
    float excess = clamp(currentDensity / requiredDensity - 0.5f, 0.0f, 1.0f);
    return 0.5f * (1.0f + cos(kPi * excess));
}

// The floor epsilon: clamped (unbiased), or below it the photon is dropped (cutoff, biased: the
// paper's second remedy). Returns 0 for a dropped photon.
INLINE float flooredAcceptance(float p, float epsilon, bool cutoff) {
    if (cutoff) return p < epsilon ? 0.0f : p;
    return max(p, epsilon);
}

SHARED_END
#endif
