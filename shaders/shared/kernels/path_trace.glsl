// Interface of the path tracer kernels (shaders/render/path_tracer.glsl: pathtrace.comp,
// guided_pathtrace.comp, guided_cached_pathtrace.comp; host/passes/path_trace_pass.h).
#ifndef VKP_KERNELS_PATH_TRACE_GLSL
#define VKP_KERNELS_PATH_TRACE_GLSL
#include "shared/compat.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

const uint kPathTraceGroupSize = 64u;

// Bindings after the scene's (0 .. kSceneBindingCount - 1).
const uint kPathTraceFilmBinding = kSceneBindingCount + 0u;          // vec4 per pixel: rgb sum, sample count
const uint kPathTraceCounterBinding = kSceneBindingCount + 1u;       // uint[kPathTraceCounterCount]
const uint kPathTraceRasterDirectBinding = kSceneBindingCount + 2u; // vec4 per pixel: raster direct light (--direct raster)
// The guide, guided_pathtrace.comp: the photon grid's cell starts and photons (photon_gather.glsl);
// guided_cached_pathtrace.comp: the guiding cache's cells, CDFs and irradiance (guide_cache.glsl).
const uint kPathTraceGuideBinding = kSceneBindingCount + 3u;
const uint kPathTraceGuideCellsBinding = kSceneBindingCount + 3u;
const uint kPathTraceGuideCdfsBinding = kSceneBindingCount + 4u;
const uint kPathTraceGuideIrradianceBinding = kSceneBindingCount + 5u;
// guided_learning_pathtrace.comp: the cache's bindings and the sums it learns (guide_learn.glsl).
const uint kPathTraceGuideLearnBinding = kSceneBindingCount + 6u;

// Slots of the counter buffer.
const uint kPathTraceCounterNonFinite = 0u;     // samples that produced a non-finite value (dropped)
const uint kPathTraceCounterSegmentsLow = 1u;   // rays traced from camera-path vertices, low word
const uint kPathTraceCounterSegmentsHigh = 2u;  // and high word (the work Russian roulette saves)
const uint kPathTraceCounterCount = 3u;

// Russian roulette by the throughput: at vertex kRouletteMinDepth (the fourth) and after, a path
// survives with probability kRouletteGain times its throughput's largest component, at most
// kRouletteMaxSurvival, and its throughput is divided by it. With gain 1 (until 2026-11-28) every
// path was thinned to throughput 1 at once, which cut most light after three bounces (light seen
// through glass, light through a slit) and made that light the largest part of the noise; with
// gain 4 a path is thinned only once its throughput is below 1/4. Equal samples, relMSE x path
// segments: 1.1-1.2x better on the Cornell boxes, 1.5x on door-slit, 2.4x on the caustic room
// (docs/benchmarks.md, "Russian roulette").
const uint kRouletteMinDepth = 3u;
const float kRouletteGain = 4.0f;
const float kRouletteMaxSurvival = 0.95f;

INLINE float rouletteSurvival(uint depth, float largestThroughput) {
    if (depth < kRouletteMinDepth) return 1.0f;
    return min(kRouletteGain * largestThroughput, kRouletteMaxSurvival);
}

SHARED_END

#ifdef __cplusplus
#include "shared/gpu_types.glsl"
#include "shared/guiding.glsl"
namespace vkp::gpu {

// Push constants of the guided variants: the path tracer's, then the guide's.
struct GuidedPathTraceParams {
    PathTraceParams params;
    GuideParams guide;
};
static_assert(sizeof(GuidedPathTraceParams) == 128, "within the guaranteed 128 bytes of push constants");

struct PathTraceKernel {
    static constexpr const char* kShader = "pathtrace.comp";
    static constexpr uint32_t kBindingCount = kPathTraceRasterDirectBinding + 1u;
    static constexpr uint32_t kGroupSize = kPathTraceGroupSize;
    using Push = PathTraceParams;
};
struct GuidedPathTraceKernel {
    static constexpr const char* kShader = "guided_pathtrace.comp";
    static constexpr uint32_t kBindingCount = kPathTraceGuideBinding + 2u;
    static constexpr uint32_t kGroupSize = kPathTraceGroupSize;
    using Push = GuidedPathTraceParams;
};
struct GuidedCachedPathTraceKernel {
    static constexpr const char* kShader = "guided_cached_pathtrace.comp";
    static constexpr uint32_t kBindingCount = kPathTraceGuideIrradianceBinding + 1u;
    static constexpr uint32_t kGroupSize = kPathTraceGroupSize;
    using Push = GuidedPathTraceParams;
};

struct GuidedLearningPathTraceKernel {
    static constexpr const char* kShader = "guided_learning_pathtrace.comp";
    static constexpr uint32_t kBindingCount = kPathTraceGuideLearnBinding + 1u;
    static constexpr uint32_t kGroupSize = kPathTraceGroupSize;
    using Push = GuidedPathTraceParams;
};
}  // namespace vkp::gpu
#endif
#endif
