// Photon-guided direction sampling (Jensen 1995, shared/papers/001): the flux of nearby photons,
// weighted by the BRDF, fills an m x n grid over the unit square that the cosine-weighted
// hemisphere mapping (sampling.glsl: theta = acos(sqrt(1 - u)), phi = 2 pi v) takes to
// directions. A cell is chosen by the grid's discrete CDF, a point uniformly inside it, and the
// direction's density is P(cell) * cells * cos(theta) / pi. Empty cells get a share of the total
// so that no direction has zero probability (the estimator stays unbiased).
//
// Shared by the guided path tracer (pathtrace.comp with GUIDED) and the host tests, which check
// that the pdf integrates to one and matches the sampling (chi-square).
#ifndef VKP_GUIDING_GLSL
#define VKP_GUIDING_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "photon_grid.glsl"
#include "normal_bins.glsl"
#include "sampling.glsl"
SHARED_BEGIN

const uint kMaxGuideCells = 64u;
// Every cell gets this fraction of the mean cell energy on top of its own.
const float kGuideEmptyCellShare = 0.1f;

// The cell of a point of the unit square: m bands of u (theta), n sectors of v (phi).
INLINE uint guideCell(vec2 uv, uint m, uint n) {
    uint iu = min(uint(uv.x * float(m)), m - 1u);
    uint iv = min(uint(uv.y * float(n)), n - 1u);
    return iu * n + iv;
}

// The cell of local direction wi (z > 0) under the cosine mapping.
INLINE uint guideDirectionCell(vec3 wi, uint m, uint n) { return guideCell(invertCosineHemisphere(wi), m, n); }

// Adds `energy` at the local direction wi (z > 0) to the grid.
INLINE void guideAdd(INOUT_ARRAY(float, cells, kMaxGuideCells), uint m, uint n, vec3 wi, float energy) {
    if (wi.z <= 0.0f || !(energy > 0.0f)) return;
    uint c = guideDirectionCell(wi, m, n);
    cells[c] = cells[c] + energy;
}

// Turns accumulated energies into a CDF in place (cells[i] = P(cell <= i), the last exactly 1):
// each cell gets kGuideEmptyCellShare of the mean on top; an empty grid becomes uniform.
INLINE void guideFinalize(INOUT_ARRAY(float, cells, kMaxGuideCells), uint m, uint n) {
    uint count = m * n;
    float total = 0.0f;
    for (uint i = 0u; i < count; ++i) total += cells[i];
    float floorShare = total > 0.0f ? kGuideEmptyCellShare * total / float(count) : 1.0f;
    float running = 0.0f;
    for (uint i = 0u; i < count; ++i) {
        running += cells[i] + floorShare;
        cells[i] = running;
    }
    for (uint i = 0u; i < count; ++i) cells[i] = cells[i] / running;
    cells[count - 1u] = 1.0f;
}

// A grid's CDF is read through a macro, CDF_AT(i), so that the same search serves a grid in a
// local array (a grid built at the vertex) and one read in place from a buffer (the guiding
// cache: copying its 64 floats into a local array at every vertex cost more than the rest of
// the guiding).

// The probability of cell c of the CDF read by CDF_AT.
#define GUIDE_CELL_PROBABILITY(CDF_AT, c) ((c) == 0u ? CDF_AT(0u) : CDF_AT(c) - CDF_AT((c) - 1u))

// Sets `c` to the first of `count` cells whose CDF (read by CDF_AT) exceeds x (the last one's is
// 1): a binary search, 6 reads for 64 cells.
#define GUIDE_FIND_CELL(CDF_AT, count, x, c)         \
    {                                               \
        c = 0u;                                     \
        uint guideLast_ = (count) - 1u;             \
        while (c < guideLast_) {                    \
            uint guideMid_ = (c + guideLast_) / 2u; \
            if ((x) >= CDF_AT(guideMid_)) c = guideMid_ + 1u; \
            else guideLast_ = guideMid_;            \
        }                                           \
    }

// Sets `wi` to the local direction of the unit-square point u under the CDF read by CDF_AT: u.x
// picks the cell, and where u.x fell within the cell's share of [0, 1), rescaled to [0, 1), is the
// point's theta coordinate inside the cell, u.y its phi coordinate. One 2-D point makes the whole
// direction, so the stratification of a pixel's 2-D points carries over to its directions (each
// cell gets its share of them, spread over the cell), as it does for BSDF sampling; a cell chosen
// by a dimension of its own would pair cells and in-cell points at random.
#define GUIDE_SAMPLE(CDF_AT, m, n, u, wi)                                                                   \
    {                                                                                                     \
        uint guideCell_;                                                                                  \
        GUIDE_FIND_CELL(CDF_AT, (m) * (n), (u).x, guideCell_)                                             \
        float guideLow_ = guideCell_ == 0u ? 0.0f : CDF_AT(guideCell_ - 1u);                              \
        float guideShare_ = CDF_AT(guideCell_) - guideLow_;                                               \
        float guideIn_ = guideShare_ > 0.0f ? clamp(((u).x - guideLow_) / guideShare_, 0.0f, kOneMinusEpsilon) : 0.5f; \
        wi = guideCellDirection(guideCell_, m, n, vec2(guideIn_, (u).y));                                \
    }

// One-sample choice between the guide (probability `mix`, 0 < mix <= 1) and the BSDF by the first
// coordinate of a unit-square point, rescaled to [0, 1) within the branch taken: each branch then
// gets a stratified set of points (with mix 1/2, exactly a net of half the points).
INLINE bool guideChosen(INOUT(vec2) u, float mix) {
    bool chosen = u.x < mix;
    u.x = chosen ? u.x / mix : (u.x - mix) / (1.0f - mix);
    u.x = min(max(u.x, 0.0f), kOneMinusEpsilon);
    return chosen;
}

// Solid-angle density of local direction wi (z > 0) in cell c of probability p.
INLINE float guideDensity(float p, uint m, uint n, vec3 wi) { return p * float(m * n) * wi.z * kInvPi; }

// A local direction in cell c of an m x n grid, from the point u inside it.
INLINE vec3 guideCellDirection(uint c, uint m, uint n, vec2 u) {
    uint iu = c / n;
    uint iv = c - iu * n;
    vec2 uv = vec2((float(iu) + u.x) / float(m), (float(iv) + u.y) / float(n));
    return sampleCosineHemisphere(vec2(min(uv.x, kOneMinusEpsilon), min(uv.y, kOneMinusEpsilon)));
}

#define GUIDE_ARRAY_AT(i) cdf[i]

INLINE float guideCellProbability(IN_ARRAY(float, cdf, kMaxGuideCells), uint c) {
    return GUIDE_CELL_PROBABILITY(GUIDE_ARRAY_AT, c);
}

// Solid-angle density of local direction wi under the guiding grid.
INLINE float guidePdf(IN_ARRAY(float, cdf, kMaxGuideCells), uint m, uint n, vec3 wi) {
    if (wi.z <= 0.0f) return 0.0f;
    return guideDensity(guideCellProbability(cdf, guideDirectionCell(wi, m, n)), m, n, wi);
}

// Samples a local direction from the unit-square point u.
INLINE vec3 guideSample(IN_ARRAY(float, cdf, kMaxGuideCells), uint m, uint n, vec2 u) {
    vec3 wi;
    GUIDE_SAMPLE(GUIDE_ARRAY_AT, m, n, u, wi)
    return wi;
}

// The guiding cache keeps one grid per cache cell and normal bin (shared/normal_bins.glsl).

// Per-cell adaptive resolution of the guiding cache (--guide-adapt P): a cache grid whose photons
// are too few for its cells is coarsened, halving phi sectors while there are at least twice as
// many as theta bands, else theta bands, until it has P photons per cell or kGuideMinAdaptiveCells
// cells. The (m, n) grid is the finest; every coarser one's cells are unions of its cells.
const uint kGuideMinAdaptiveCells = 8u;

INLINE uvec2 guideAdaptiveSize(uint m, uint n, uint photonsPerCell, float photons) {
    while (m * n > kGuideMinAdaptiveCells && photons < float(photonsPerCell * m * n)) {
        if (n >= 2u * m && n % 2u == 0u) n = n / 2u;
        else if (m % 2u == 0u) m = m / 2u;
        else break;
    }
    return uvec2(m, n);
}

// Merges an (m, n) grid's energies into the coarser (m2, n2) grid in place (m2 divides m, n2
// divides n); the cells past m2 * n2 become zero. A coarse cell's sources all lie at or after its
// own index, so ascending order never reads a written cell.
INLINE void guideCoarsen(INOUT_ARRAY(float, cells, kMaxGuideCells), uint m, uint n, uint m2, uint n2) {
    if (m2 == m && n2 == n) return;
    uint fm = m / m2;
    uint fn = n / n2;
    for (uint c = 0u; c < m2 * n2; ++c) {
        uint iu2 = c / n2;
        uint iv2 = c - iu2 * n2;
        float sum = 0.0f;
        for (uint iu = iu2 * fm; iu < (iu2 + 1u) * fm; ++iu)
            for (uint iv = iv2 * fn; iv < (iv2 + 1u) * fn; ++iv) sum += cells[iu * n + iv];
        cells[c] = sum;
    }
    for (uint c = m2 * n2; c < kMaxGuideCells; ++c) cells[c] = 0.0f;
}

// Guide-driven Russian roulette (--guide-rr on), after Vorba and Krivanek, "Adjoint-Driven Russian
// Roulette and Splitting in Light Transport Simulation" (2016): at a vertex, the path's expected
// further contribution is its throughput times the radiance the vertex reflects from indirect
// light, estimated from the guiding photons' irradiance. Measured against the pixel's value (the
// reference: what the path has gathered so far plus that expectation, at its first vertex with an
// estimate), a path whose ratio falls below the weight window's lower bound 2 / (1 + s) survives
// with probability `ratio` (a survivor then sits at the window's centre); others go on. There is
// no splitting. Any survival probability above zero keeps the estimator unbiased; the floor
// bounds the weight where the estimate says "nothing" but some light still arrives.
const float kGuideRouletteWindow = 5.0f;        // s, the weight window's width (the paper's value)
const float kGuideRouletteMinSurvival = 0.05f;

// Survival probability of a path expected to bring `expected` (luminance) more, against `reference`.
INLINE float guideSurvival(float expected, float reference) {
    if (!(reference > 0.0f)) return 1.0f;
    float ratio = expected / reference;
    if (!(ratio < 2.0f / (1.0f + kGuideRouletteWindow))) return 1.0f;  // in the window, or NaN
    return max(ratio, kGuideRouletteMinSurvival);
}

// Push constants the guided path tracer adds after PathTraceParams.
struct GuideParams {
    PhotonGridView grid;  // the guiding photon map (with the cache: the cache's cells)
    float mix;            // probability of sampling the grid (else the BSDF); 1: the paper's method
    uint k;               // nearest photons per grid (<= kMaxGatherK)
    float maxRadius;      // world units
    uint gridSize;        // m | (n << 8) | (P << 16): m * n <= kMaxGuideCells, P photons per cell
                          // for the cache's adaptive resolution (0: off)
};
STATIC_ASSERT_SIZE(GuideParams, 32)

SHARED_END
#endif
