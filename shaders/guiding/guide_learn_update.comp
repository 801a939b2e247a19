// Learning the guiding cache's grids from the guided path tracer's samples (host/guiding/
// guide_learning.h): one invocation per cache grid. A reset (before a render's first sample)
// restores the photons' CDF and clears the grid's sums; an update (between sample iterations)
// blends the photons' distribution with the one the samples learned, by how many samples it has
// (kGuideLearnPriorSamples), and stores the CDF the next iteration samples.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/guide_learn.glsl"
#include "shared/guiding.glsl"

layout(local_size_x = kGuideLearnGroupSize) in;

layout(std430, set = 0, binding = kGuideLearnPriorBinding) readonly buffer Prior { float prior[]; };
layout(std430, set = 0, binding = kGuideLearnIrradianceBinding) readonly buffer Irradiance { vec4 cacheIrradiance[]; };
layout(std430, set = 0, binding = kGuideLearnSumsBinding) buffer Sums { vec4 learnHeader; uvec2 learned[]; };
layout(std430, set = 0, binding = kGuideLearnCdfsBinding) writeonly buffer Cdfs { float cacheCdfs[]; };

layout(push_constant) uniform Push { GuideLearnParams learn; };

float sumOf(uvec2 words) { return float(words.y) * 4294967296.0f + float(words.x); }

void restorePrior(uint grid) {
    for (uint i = 0u; i < kMaxGuideCells; ++i) cacheCdfs[grid * kMaxGuideCells + i] = prior[grid * kMaxGuideCells + i];
}

void main() {
    uint grid = gl_GlobalInvocationID.x;
    if (grid >= learn.gridCount) return;
    uint sums = grid * kGuideLearnStride;
    if (learn.reset != 0u) {
        if (grid == 0u) learnHeader = vec4(learn.scale, 0.0f, 0.0f, 0.0f);
        for (uint i = 0u; i < kGuideLearnStride; ++i) learned[sums + i] = uvec2(0u);
        restorePrior(grid);
        return;
    }
    uint m = learn.gridSize & 0xffu;
    uint n = (learn.gridSize >> 8u) & 0xffu;
    float cells[kMaxGuideCells];
    float total = 0.0f;
    for (uint i = 0u; i < kMaxGuideCells; ++i) {
        cells[i] = i < m * n ? sumOf(learned[sums + i]) : 0.0f;
        total += cells[i];
    }
    float samples = sumOf(learned[sums + kGuideLearnCountSlot]);
    if (!(total > 0.0f)) {  // nothing learned (no sample, or none found light): the photons' grid
        restorePrior(grid);
        return;
    }
    // The resolution the lookups use (--guide-adapt): the prior's, recomputed from its photons.
    uint photonsPerCell = learn.gridSize >> 16u;
    uvec2 size = photonsPerCell > 0u ? guideAdaptiveSize(m, n, photonsPerCell, cacheIrradiance[grid].w) : uvec2(m, n);
    guideCoarsen(cells, m, n, size.x, size.y);
    float learnedShare = samples / (samples + kGuideLearnPriorSamples);
    uint base = grid * kMaxGuideCells;
    float below = 0.0f;
    for (uint c = 0u; c < size.x * size.y; ++c) {
        float p = prior[base + c] - below;  // the photons' probability of cell c
        below = prior[base + c];
        cells[c] = (1.0f - learnedShare) * p + learnedShare * cells[c] / total;
    }
    guideFinalize(cells, size.x, size.y);
    for (uint i = 0u; i < kMaxGuideCells; ++i) cacheCdfs[base + i] = cells[i];
}
