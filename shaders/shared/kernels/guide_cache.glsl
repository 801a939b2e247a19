// Interface of guide_cache_build.comp (host/photon/guide_cache.h). The guided path tracer reads
// the cache it writes (shared/kernels/path_trace.glsl).
#ifndef VKP_KERNELS_GUIDE_CACHE_GLSL
#define VKP_KERNELS_GUIDE_CACHE_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kGuideCacheGroupSize = 64u;  // one invocation per (bucket, normal bin)

const uint kGuideCacheCellStartBinding = 0u;   // the coarse grid's cell starts
const uint kGuideCachePhotonBinding = 1u;      // and its photons, in bucket order
const uint kGuideCacheCellsBinding = 2u;       // ivec4 per bucket: xyz cell, w 1 when used
const uint kGuideCacheCdfsBinding = 3u;        // float[kMaxGuideCells] per bucket and normal bin
const uint kGuideCacheIrradianceBinding = 4u;  // vec4 per bucket and normal bin: rgb W/m^2, w photons

SHARED_END

#ifdef __cplusplus
#include "shared/guiding.glsl"
namespace vkp::gpu {

struct GuideCacheBuildKernel {
    static constexpr const char* kShader = "guide_cache_build.comp";
    static constexpr uint32_t kBindingCount = kGuideCacheIrradianceBinding + 1u;
    static constexpr uint32_t kGroupSize = kGuideCacheGroupSize;
    using Push = GuideParams;
};

}  // namespace vkp::gpu
#endif
#endif
