// Which light next-event estimation samples at a shading point (--light-sampler), and the
// probability of that choice, which the MIS weight of emission found by BSDF sampling needs for
// the light it hit:
//   selectLight(lightCount, p, n, u)          -> LightChoice { index, pdf } (pdf 0: no light)
//   selectLightPdf(lightCount, p, n, index)   -> the pdf selectLight draws `index` with
// p and n are the shading point and its shading normal (either side); both calls must get the
// same ones. Modes:
//   power  lights in proportion to emitted power (the CDF, lights[i].selectPdf)
//   bvh    a light BVH walked stochastically by node importance (shared/light_tree.glsl); lights
//          outside the tree (directional, and any light type without bounds) are chosen with
//          probability infinite / (infinite + 1), uniformly among themselves (pbrt-v4's split)
//   photon per spatial cell, the lights whose primary photons arrive there, mixed with the bvh
//          choice at a floor probability (Keller & Wald 2000, section 3; see lightCellsStart)
//
// The light-selection buffer (scene binding kSceneLightCdfBinding, floats; integers as their bits)
// holds, after the lightCount CDF entries:
//   [L + 0] mode  [L + 1] tree nodes  [L + 2] lights outside the tree
//   [L + 3] 1: emissive triangles sampled by area only (--triangle-sampling area), 0: solid angle
//   [L + 4, 2L + 4)              each light's path from the root (bit d: second child at depth d)
//   [2L + 4, 2L + 4 + infinite)  the lights outside the tree
//   then the nodes, kLightNodeFloats each, depth first (root at 0, first child right after its parent)
//
// Reached through LIGHT_SELECTION(i) (the buffer) and LIGHT(i) (GpuLight):
//  - GLSL: the including shader declares `lightCdf[]` and `lights[]` (scene_access.glsl does);
//  - C++: every function takes a LightSelectionArrays first (LIGHT_SELECTION_PARAM).
#ifndef VKP_LIGHT_SELECTION_GLSL
#define VKP_LIGHT_SELECTION_GLSL
#include "compat.glsl"
#include "gpu_types.glsl"
#include "light_tree.glsl"
#include "photon_grid.glsl"
#include "kernels/scene.glsl"
#ifdef __cplusplus
#include <span>
#endif
SHARED_BEGIN

#ifdef __cplusplus
struct LightSelectionArrays {
    std::span<const float> data;        // SceneArrays::lightCdf (CDF, header, tree)
    std::span<const GpuLight> lights;
};
#define LIGHT_SELECTION_PARAM const LightSelectionArrays& lightArrays,
#define LIGHT_SELECTION_ARG lightArrays,
#define LIGHT_SELECTION(i) lightArrays.data[i]
#define LIGHT(i) lightArrays.lights[i]
#else
#define LIGHT_SELECTION_PARAM
#define LIGHT_SELECTION_ARG
#define LIGHT_SELECTION(i) lightCdf[i]
#define LIGHT(i) lights[i]
#endif

const uint kLightSamplerPower = 0u;
const uint kLightSamplerBvh = 1u;
const uint kLightSamplerPhoton = 2u;
const uint kLightCellMaxK = 64u;  // most candidates per cell (--light-cell-k)
const uint kLightSelectionHeaderFloats = 4u;

struct LightChoice {
    uint index;
    float pdf;   // probability of the choice; 0: no light can be chosen here
};

INLINE uint lightSelectionWord(LIGHT_SELECTION_PARAM uint i) {
    return floatBitsToUint(LIGHT_SELECTION(i));
}

// The scene's light sampler as a specialization constant (vk::SceneSpecialization):
// lavapipe runs every branch of selectLight and selectLightPdf for the whole SIMD group, the light
// tree's loops included, whatever the mode; a kernel compiled for the mode drops the others.
// kLightSamplerAny (the default, and the host's): the mode word of the selection data decides.
const uint kLightSamplerAny = 0xffffffffu;
#ifdef __cplusplus
constexpr uint kSceneLightSampler = kLightSamplerAny;
#else
layout(constant_id = kSceneLightSamplerId) const uint kSceneLightSampler = kLightSamplerAny;
#endif

INLINE uint lightSamplerMode(LIGHT_SELECTION_PARAM uint lightCount) {
    if (kSceneLightSampler != kLightSamplerAny) return kSceneLightSampler;
    return lightSelectionWord(LIGHT_SELECTION_ARG lightCount);
}

// Whether emissive triangles may be sampled by solid angle (shared/spherical_triangle.glsl).
INLINE bool triangleSolidAngleSampling(LIGHT_SELECTION_PARAM uint lightCount) {
    return lightSelectionWord(LIGHT_SELECTION_ARG lightCount + 3u) == 0u;
}

INLINE uint lightTreeNodesStart(uint lightCount, uint infiniteCount) {
    return 2u * lightCount + kLightSelectionHeaderFloats + infiniteCount;
}

INLINE GpuLightNode lightTreeNode(LIGHT_SELECTION_PARAM uint nodesStart, uint node) {
    uint o = nodesStart + node * kLightNodeFloats;
    GpuLightNode b;
    b.boundsMin = vec3(LIGHT_SELECTION(o + 0u), LIGHT_SELECTION(o + 1u), LIGHT_SELECTION(o + 2u));
    b.power = LIGHT_SELECTION(o + 3u);
    b.boundsMax = vec3(LIGHT_SELECTION(o + 4u), LIGHT_SELECTION(o + 5u), LIGHT_SELECTION(o + 6u));
    b.cosThetaO = LIGHT_SELECTION(o + 7u);
    b.axis = vec3(LIGHT_SELECTION(o + 8u), LIGHT_SELECTION(o + 9u), LIGHT_SELECTION(o + 10u));
    b.cosThetaE = LIGHT_SELECTION(o + 11u);
    b.childOrLight = lightSelectionWord(LIGHT_SELECTION_ARG o + 12u);
    b.flags = lightSelectionWord(LIGHT_SELECTION_ARG o + 13u);
    b.pad0 = 0u;
    b.pad1 = 0u;
    return b;
}

// Probability of choosing among the lights outside the tree.
INLINE float lightInfiniteProbability(uint nodeCount, uint infiniteCount) {
    if (infiniteCount == 0u) return 0.0f;
    return float(infiniteCount) / float(infiniteCount + (nodeCount > 0u ? 1u : 0u));
}

// Power sampling: binary search of u in the CDF.
INLINE uint pickLightByPower(LIGHT_SELECTION_PARAM float u, uint lightCount) {
    uint lo = 0u;
    uint hi = lightCount - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (u < LIGHT_SELECTION(mid)) hi = mid; else lo = mid + 1u;
    }
    return lo;
}

// The light BVH's choice at p (u in [0, 1)).
INLINE LightChoice selectLightBvh(LIGHT_SELECTION_PARAM uint lightCount, vec3 p, vec3 n, float u) {
    LightChoice c;
    c.index = 0u;
    c.pdf = 0.0f;
    uint nodeCount = lightSelectionWord(LIGHT_SELECTION_ARG lightCount + 1u);
    uint infiniteCount = lightSelectionWord(LIGHT_SELECTION_ARG lightCount + 2u);
    float pInfinite = lightInfiniteProbability(nodeCount, infiniteCount);
    if (u < pInfinite) {
        uint k = min(uint(u / pInfinite * float(infiniteCount)), infiniteCount - 1u);
        c.index = lightSelectionWord(LIGHT_SELECTION_ARG 2u * lightCount + kLightSelectionHeaderFloats + k);
        c.pdf = pInfinite / float(infiniteCount);
        return c;
    }
    if (nodeCount == 0u) return c;
    u = min((u - pInfinite) / (1.0f - pInfinite), kOneMinusEpsilon);
    uint nodesStart = lightTreeNodesStart(lightCount, infiniteCount);
    uint node = 0u;
    float pdf = 1.0f - pInfinite;
    for (uint depth = 0u; depth <= kLightTreeMaxDepth; ++depth) {
        GpuLightNode b = lightTreeNode(LIGHT_SELECTION_ARG nodesStart, node);
        if ((b.flags & kLightNodeLeaf) != 0u) {
            if (depth == 0u && lightNodeImportance(b, p, n) <= 0.0f) return c;
            c.index = b.childOrLight;
            c.pdf = pdf;
            return c;
        }
        float i0 = lightNodeImportance(lightTreeNode(LIGHT_SELECTION_ARG nodesStart, node + 1u), p, n);
        float i1 = lightNodeImportance(lightTreeNode(LIGHT_SELECTION_ARG nodesStart, b.childOrLight), p, n);
        if (i0 <= 0.0f && i1 <= 0.0f) return c;
        float p0 = i0 / (i0 + i1);
        if (u < p0) {
            node = node + 1u;
            u = min(u / p0, kOneMinusEpsilon);
            pdf *= p0;
        } else {
            node = b.childOrLight;
            u = min((u - p0) / (1.0f - p0), kOneMinusEpsilon);
            pdf *= 1.0f - p0;
        }
    }
    return c;
}

// The probability that selectLightBvh chooses light `index` at p.
INLINE float selectLightBvhPdf(LIGHT_SELECTION_PARAM uint lightCount, vec3 p, vec3 n, uint index) {
    uint nodeCount = lightSelectionWord(LIGHT_SELECTION_ARG lightCount + 1u);
    uint infiniteCount = lightSelectionWord(LIGHT_SELECTION_ARG lightCount + 2u);
    float pInfinite = lightInfiniteProbability(nodeCount, infiniteCount);
    uint type = LIGHT(index).type;
    if (type != kLightTriangle && type != kLightPoint && type != kLightSpot)
        return infiniteCount > 0u ? pInfinite / float(infiniteCount) : 0.0f;
    if (nodeCount == 0u) return 0.0f;
    uint trail = lightSelectionWord(LIGHT_SELECTION_ARG lightCount + kLightSelectionHeaderFloats + index);
    uint nodesStart = lightTreeNodesStart(lightCount, infiniteCount);
    uint node = 0u;
    float pdf = 1.0f - pInfinite;
    for (uint depth = 0u; depth <= kLightTreeMaxDepth; ++depth) {
        GpuLightNode b = lightTreeNode(LIGHT_SELECTION_ARG nodesStart, node);
        if ((b.flags & kLightNodeLeaf) != 0u) {
            if (depth == 0u && lightNodeImportance(b, p, n) <= 0.0f) return 0.0f;
            return b.childOrLight == index ? pdf : 0.0f;
        }
        float i0 = lightNodeImportance(lightTreeNode(LIGHT_SELECTION_ARG nodesStart, node + 1u), p, n);
        float i1 = lightNodeImportance(lightTreeNode(LIGHT_SELECTION_ARG nodesStart, b.childOrLight), p, n);
        if (i0 <= 0.0f && i1 <= 0.0f) return 0.0f;
        float p0 = i0 / (i0 + i1);
        if ((trail & 1u) == 0u) {
            node = node + 1u;
            pdf *= p0;
        } else {
            node = b.childOrLight;
            pdf *= 1.0f - p0;
        }
        trail = trail >> 1u;
    }
    return 0.0f;
}

// Photon light cells (--light-sampler photon, Keller & Wald 2000 section 3). After the tree nodes:
//   [C + 0] 1 / cell size  [C + 1] table mask (buckets - 1)  [C + 2] K  [C + 3] floor probability
//   then per bucket 4 + 2K words: cell x, y, z (int bits), candidate count m (0: empty bucket),
//   then K pairs (light index, cumulative probability), the first m used.
// A bucket holds the lights whose primary photons arrived in its cell, up to the K that delivered
// the most power, with probabilities in proportion to that power. At p, with probability `floor`
// the light comes from the light BVH (every light that can reach p has a chance: unbiased), else
// from p's cell; cells without photons (or lost to a hash collision) use the BVH alone.
INLINE uint lightCellsStart(LIGHT_SELECTION_PARAM uint lightCount) {
    uint nodeCount = lightSelectionWord(LIGHT_SELECTION_ARG lightCount + 1u);
    uint infiniteCount = lightSelectionWord(LIGHT_SELECTION_ARG lightCount + 2u);
    return lightTreeNodesStart(lightCount, infiniteCount) + nodeCount * kLightNodeFloats;
}

INLINE uint lightCellBucketFloats(uint k) {
    return 4u + 2u * k;
}

// Start of p's bucket, or 0 when p's cell has no candidates (0 is never a bucket's start).
INLINE uint lightCellAt(LIGHT_SELECTION_PARAM uint cellsStart, vec3 p) {
    float invCellSize = LIGHT_SELECTION(cellsStart);
    uint mask = lightSelectionWord(LIGHT_SELECTION_ARG cellsStart + 1u);
    uint k = lightSelectionWord(LIGHT_SELECTION_ARG cellsStart + 2u);
    ivec3 cell = gridCell(p, invCellSize);
    uint bucket = cellsStart + 4u + gridHash(cell, mask) * lightCellBucketFloats(k);
    if (lightSelectionWord(LIGHT_SELECTION_ARG bucket + 3u) == 0u) return 0u;
    if (int(lightSelectionWord(LIGHT_SELECTION_ARG bucket)) != cell.x ||
        int(lightSelectionWord(LIGHT_SELECTION_ARG bucket + 1u)) != cell.y ||
        int(lightSelectionWord(LIGHT_SELECTION_ARG bucket + 2u)) != cell.z)
        return 0u;
    return bucket;
}

// Probability of `index` in the bucket's distribution.
INLINE float lightCellPdf(LIGHT_SELECTION_PARAM uint bucket, uint index) {
    uint m = min(lightSelectionWord(LIGHT_SELECTION_ARG bucket + 3u), kLightCellMaxK);
    float previous = 0.0f;
    for (uint j = 0u; j < m; ++j) {
        float cdf = LIGHT_SELECTION(bucket + 4u + 2u * j + 1u);
        if (lightSelectionWord(LIGHT_SELECTION_ARG bucket + 4u + 2u * j) == index) return cdf - previous;
        previous = cdf;
    }
    return 0.0f;
}

INLINE LightChoice selectLight(LIGHT_SELECTION_PARAM uint lightCount, vec3 p, vec3 n, float u) {
    LightChoice c;
    c.index = 0u;
    c.pdf = 0.0f;
    if (lightCount == 0u) return c;
    uint mode = lightSamplerMode(LIGHT_SELECTION_ARG lightCount);
    if (mode == kLightSamplerBvh) return selectLightBvh(LIGHT_SELECTION_ARG lightCount, p, n, u);
    if (mode == kLightSamplerPhoton) {
        uint cellsStart = lightCellsStart(LIGHT_SELECTION_ARG lightCount);
        uint bucket = lightCellAt(LIGHT_SELECTION_ARG cellsStart, p);
        if (bucket == 0u) return selectLightBvh(LIGHT_SELECTION_ARG lightCount, p, n, u);
        float floorP = LIGHT_SELECTION(cellsStart + 3u);
        if (u < floorP) {
            c = selectLightBvh(LIGHT_SELECTION_ARG lightCount, p, n, min(u / floorP, kOneMinusEpsilon));
            if (c.pdf <= 0.0f) return c;
            c.pdf = floorP * c.pdf + (1.0f - floorP) * lightCellPdf(LIGHT_SELECTION_ARG bucket, c.index);
            return c;
        }
        u = min((u - floorP) / (1.0f - floorP), kOneMinusEpsilon);
        uint m = min(lightSelectionWord(LIGHT_SELECTION_ARG bucket + 3u), kLightCellMaxK);
        float previous = 0.0f;
        for (uint j = 0u; j < m; ++j) {
            float cdf = LIGHT_SELECTION(bucket + 4u + 2u * j + 1u);
            if (u < cdf || j + 1u == m) {
                c.index = lightSelectionWord(LIGHT_SELECTION_ARG bucket + 4u + 2u * j);
                c.pdf = (1.0f - floorP) * (cdf - previous) +
                        floorP * selectLightBvhPdf(LIGHT_SELECTION_ARG lightCount, p, n, c.index);
                return c;
            }
            previous = cdf;
        }
        return c;
    }
    c.index = pickLightByPower(LIGHT_SELECTION_ARG u, lightCount);
    c.pdf = LIGHT(c.index).selectPdf;
    return c;
}

INLINE float selectLightPdf(LIGHT_SELECTION_PARAM uint lightCount, vec3 p, vec3 n, uint index) {
    if (index >= lightCount) return 0.0f;
    uint mode = lightSamplerMode(LIGHT_SELECTION_ARG lightCount);
    if (mode == kLightSamplerBvh) return selectLightBvhPdf(LIGHT_SELECTION_ARG lightCount, p, n, index);
    if (mode == kLightSamplerPhoton) {
        float bvh = selectLightBvhPdf(LIGHT_SELECTION_ARG lightCount, p, n, index);
        uint cellsStart = lightCellsStart(LIGHT_SELECTION_ARG lightCount);
        uint bucket = lightCellAt(LIGHT_SELECTION_ARG cellsStart, p);
        if (bucket == 0u) return bvh;
        float floorP = LIGHT_SELECTION(cellsStart + 3u);
        return floorP * bvh + (1.0f - floorP) * lightCellPdf(LIGHT_SELECTION_ARG bucket, index);
    }
    return LIGHT(index).selectPdf;
}

SHARED_END
#endif
