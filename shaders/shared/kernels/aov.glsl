// Interface of aov.comp (host/render/aov.h): the auxiliary images of --aov — albedo, normal and
// depth of the first surface without a delta lobe along each pixel's camera rays.
#ifndef VKP_KERNELS_AOV_GLSL
#define VKP_KERNELS_AOV_GLSL
#include "shared/compat.glsl"
#include "shared/gpu_types.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

const uint kAovGroupSize = 64u;
// Bindings after the scene's (0 .. kSceneBindingCount - 1).
const uint kAovAlbedoBinding = kSceneBindingCount + 0u;   // vec4 per pixel: albedo (rgb), w unused
const uint kAovNormalBinding = kSceneBindingCount + 1u;   // vec4 per pixel: world-space unit normal (xyz), depth in metres (w)
// Camera rays per pixel whose albedo and normal are averaged (the first through the centre,
// which alone gives the depth).
const uint kAovSamples = 8u;
// Depth of pixels that see no surface (Blender's background depth).
const float kAovBackgroundDepth = 1.0e10f;

struct AovParams {
    GpuCamera camera;
    uint width;
    uint height;
    uint seed;
    uint maxSpecularDepth;  // delta bounces followed to the first non-delta surface
};
STATIC_ASSERT_SIZE(AovParams, 80)

SHARED_END

#ifdef __cplusplus
namespace vkp::gpu {
struct AovKernel {
    static constexpr const char* kShader = "aov.comp";
    static constexpr uint32_t kBindingCount = kAovNormalBinding + 1u;
    static constexpr uint32_t kGroupSize = kAovGroupSize;
    using Push = AovParams;
};
}  // namespace vkp::gpu
#endif
#endif
