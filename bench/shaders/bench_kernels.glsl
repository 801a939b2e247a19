// Interfaces of the benchmark kernels in bench/shaders/, declared once for the shaders and the
// benchmarks as shaders/shared/kernels/ does for the renderer's.
#ifndef VKP_BENCH_KERNELS_GLSL
#define VKP_BENCH_KERNELS_GLSL
#include "shared/compat.glsl"
#include "shared/gpu_types.glsl"
#include "shared/photon_grid.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

const uint kBenchGroupSize = 64u;

// gather_throughput.comp: a query at every stride-th photon of a map.
const uint kGatherBenchGridBinding = 0u;    // the map's grid: cell starts, photons at 1 (photon_gather.glsl)
const uint kGatherBenchResultBinding = 2u;  // float per query
struct GatherBenchParams {
    PhotonGridView grid;
    uint queries;
    uint stride;
    uint mode;                              // 0 fixed radius, 1 k nearest, 2 nearest radiance photon
    uint k;
    float radius;
};
STATIC_ASSERT_SIZE(GatherBenchParams, 36)

// ray_throughput.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kRayBenchResultBinding = kSceneBindingCount + 0u;     // uint per pixel: hits
struct RayBenchParams {
    GpuCamera camera;
    uint width;
    uint height;
    uint mode;                              // 0 camera rays, 1 a diffuse bounce from each camera hit
    uint seed;
};
STATIC_ASSERT_SIZE(RayBenchParams, 80)

// traced_direct.comp: the scene's (0 .. kSceneBindingCount - 1), then; push constants: RasterDirectParams.
const uint kTracedDirectLightBinding = kSceneBindingCount + 0u;  // GpuLight: the raster lights
const uint kTracedDirectOutputBinding = kSceneBindingCount + 1u; // vec4 per pixel

SHARED_END

#ifdef __cplusplus
#include "shared/shadow_volume.glsl"
namespace vkp::gpu {

struct GatherBenchKernel {
    static constexpr const char* kShader = "gather_throughput.comp";
    static constexpr uint32_t kBindingCount = kGatherBenchResultBinding + 1u;
    static constexpr uint32_t kGroupSize = kBenchGroupSize;
    using Push = GatherBenchParams;
};
struct RayBenchKernel {
    static constexpr const char* kShader = "ray_throughput.comp";
    static constexpr uint32_t kBindingCount = kRayBenchResultBinding + 1u;
    static constexpr uint32_t kGroupSize = kBenchGroupSize;
    using Push = RayBenchParams;
};
struct TracedDirectKernel {
    static constexpr const char* kShader = "traced_direct.comp";
    static constexpr uint32_t kBindingCount = kTracedDirectOutputBinding + 1u;
    static constexpr uint32_t kGroupSize = kBenchGroupSize;
    using Push = RasterDirectParams;
};

}  // namespace vkp::gpu
#endif
#endif
