// Interface of the raster direct light's compute kernels: shadow_volume_build.comp and
// raster_direct.comp (host/passes/shadow_volume_pass.h, raster_direct_pass.h).
#ifndef VKP_KERNELS_RASTER_DIRECT_GLSL
#define VKP_KERNELS_RASTER_DIRECT_GLSL
#include "shared/compat.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

// shadow_volume_build.comp: one invocation per (triangle, light)
const uint kShadowVolumeGroupSize = 64u;
const uint kShadowVolumeTriangleBinding = 0u;  // GpuShadowTriangle, BVH order
const uint kShadowVolumeLightBinding = 1u;     // GpuLight: the raster lights
const uint kShadowVolumeVertexBinding = 2u;    // vec4[kVolumeVerticesPerTriangle] per (triangle, light)

// raster_direct.comp: one invocation per pixel; the scene's (0 .. kSceneBindingCount - 1), then
const uint kRasterDirectGroupSize = 64u;
const uint kRasterDirectLightBinding = kSceneBindingCount + 0u;     // GpuLight: the raster lights
const uint kRasterDirectMaskBinding = kSceneBindingCount + 1u;      // uint per pixel and mask pass: RGBA8, a light per channel
const uint kRasterDirectOutputBinding = kSceneBindingCount + 2u;   // vec4 per pixel: direct light, summed over the passes

SHARED_END

#ifdef __cplusplus
#include "shared/shadow_volume.glsl"
namespace vkp::gpu {

struct ShadowVolumeBuildKernel {
    static constexpr const char* kShader = "shadow_volume_build.comp";
    static constexpr uint32_t kBindingCount = kShadowVolumeVertexBinding + 1u;
    static constexpr uint32_t kGroupSize = kShadowVolumeGroupSize;
    using Push = ShadowVolumeParams;
};
struct RasterDirectKernel {
    static constexpr const char* kShader = "raster_direct.comp";
    static constexpr uint32_t kBindingCount = kRasterDirectOutputBinding + 1u;
    static constexpr uint32_t kGroupSize = kRasterDirectGroupSize;
    using Push = RasterDirectParams;
};

}  // namespace vkp::gpu
#endif
#endif
