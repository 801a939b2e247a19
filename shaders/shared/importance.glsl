// Importance-driven photon deposition (docs/importance-deposition.md): importons shot from the
// camera, the deposition probability of Keller & Wald (2000, shared/papers/000) and the density
// control of Suykens & Willems (2000, shared/papers/002). Shared by importon_trace.comp,
// importance_lookup.comp, photon_deposit.comp and the host.
#ifndef VKP_IMPORTANCE_GLSL
#define VKP_IMPORTANCE_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "gpu_types.glsl"
#include "photon_grid.glsl"
SHARED_BEGIN

// How photons are kept at deposition (--deposit).
const uint kDepositAll = 0u;         // every photon (Jensen's photon map)
const uint kDepositImportance = 1u;  // kept with p = min(1, f * importance density) (Keller & Wald)
const uint kDepositDensity = 2u;     // kept by the ratio of current to required density (Suykens & Willems)

// An importon is stored as a GpuPhoton: the red "power" channel holds its visual importance W
// (the luminance of the camera path's throughput; every importon path carries 1), the green one
// its path importance for density control (Suykens & Willems eq. 4 for a path eye -> y -> x:
// f_r(y) cos(y) cos(x) / |x - y|^2, times the albedo of earlier bounces; 0 where the camera sees
// the point directly), and kPhotonPrimary marks the importons the camera sees directly.

// Largest finite value a record's half-float channels hold.
const float kMaxHalfFloat = 65504.0f;

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

// Push constants of importance_lookup.comp: for every photon slot, the importance density and
// the largest path importance among the k nearest importons.
struct ImportanceLookupParams {
    PhotonGridView importons;
    uint slotCount;
    uint k;                  // nearest importons per lookup (<= kMaxGatherK)
    float maxRadius;         // search radius; fewer than k importons within it: the disk of this radius
    uint requiredFlags;      // only the photons the map keeps are looked up (photonSelected)
    uint rejectedFlags;
    uint pad0;
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(ImportanceLookupParams, 48)

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
    uint pad0;
};
STATIC_ASSERT_SIZE(PhotonDepositParams, 80)

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
