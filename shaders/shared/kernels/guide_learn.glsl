// Interface of guide_learn_update.comp (host/guiding/guide_learning.h): the guiding cache's grids
// refined by the guided path tracer's own samples (docs/guided-path-tracing.md, "Learning from
// the path tracer's samples"). The learning path tracer (guided_learning_pathtrace.comp) adds each
// guided vertex's sampled incident radiance to its grid's direction cell; between sample
// iterations this kernel turns the sums into the grids' CDFs, blended with the photons' grid.
#ifndef VKP_KERNELS_GUIDE_LEARN_GLSL
#define VKP_KERNELS_GUIDE_LEARN_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kGuideLearnGroupSize = 64u;  // one invocation per cache grid (bucket, normal bin)

const uint kGuideLearnPriorBinding = 0u;       // float[kMaxGuideCells] per grid: the photons' CDF
const uint kGuideLearnIrradianceBinding = 1u;  // vec4 per grid (w: photons, for --guide-adapt)
const uint kGuideLearnSumsBinding = 2u;        // vec4 header (x: radiance scale), then the sums
const uint kGuideLearnCdfsBinding = 3u;        // float[kMaxGuideCells] per grid: the CDF paths sample

// The sums, after the header: per grid, kGuideLearnStride 64-bit integers (uvec2: low, high word),
// one per direction cell of the full --guide-grid resolution, then the number of samples.
const uint kGuideLearnStride = 65u;
const uint kGuideLearnCountSlot = 64u;

// Path vertices per path whose incident radiance is learned (the first guided ones): further
// bounces carry little of a pixel's light and each costs a record in every invocation.
const uint kGuideLearnVertices = 4u;  // guide_learning.glsl keeps them in four variables

// A sample adds luminance(incident radiance) * cos / pdf, in units of the scene's mean radiance
// (the header's scale: emitted power / (pi * surface area)) times kGuideLearnFixedPoint, rounded
// to an integer: integer sums are the same in any order, so a seed gives the same image on every
// run. A sample adds at most kGuideLearnMaxSample (2^31: 500,000 times the mean radiance).
const float kGuideLearnFixedPoint = 4096.0f;
const float kGuideLearnMaxSample = 2147483648.0f;

// The photons' grid counts as this many samples: with N samples learned, the grid samples
// (prior * kGuideLearnPriorSamples + learned * N) / (kGuideLearnPriorSamples + N).
const float kGuideLearnPriorSamples = 64.0f;

struct GuideLearnParams {
    uint gridCount;  // cache grids: buckets * kNormalBins
    uint gridSize;   // GuideParams::gridSize (m | n << 8 | P << 16)
    uint reset;      // 1: restore the photons' CDFs and clear the sums (a render's first sample)
    float scale;     // the header's radiance scale, written by a reset
};
STATIC_ASSERT_SIZE(GuideLearnParams, 16)

SHARED_END

#ifdef __cplusplus
namespace vkp::gpu {

struct GuideLearnUpdateKernel {
    static constexpr const char* kShader = "guide_learn_update.comp";
    static constexpr uint32_t kBindingCount = kGuideLearnCdfsBinding + 1u;
    static constexpr uint32_t kGroupSize = kGuideLearnGroupSize;
    using Push = GuideLearnParams;
};

}  // namespace vkp::gpu
#endif
#endif
