// Interface of the photon integrator's camera-side kernels: visible_points.comp and the
// estimates at the visible points, caustic_estimate.comp, final_gather.comp, gather_reuse.comp, sppm_update.comp,
// with radiance_photons.comp, which precomputes what final gathers read
// (host/photon/visible_point_pass.h, caustic_estimate_pass.h, final_gather_pass.h,
// sppm_update_pass.h, radiance_photons.h). A grid binding holds the photon grid's cell starts and
// the next binding its photons (shaders/photon/photon_gather.glsl).
#ifndef VKP_KERNELS_PHOTON_ESTIMATES_GLSL
#define VKP_KERNELS_PHOTON_ESTIMATES_GLSL
#include "shared/compat.glsl"
#include "shared/kernels/scene.glsl"
SHARED_BEGIN

const uint kPhotonEstimateGroupSize = 64u;  // one invocation per pixel (per photon: radiance photons)

// visible_points.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kVisiblePointsFilmBinding = kSceneBindingCount + 0u;          // vec4 per pixel: rgb sum, sample count
const uint kVisiblePointsPointBinding = kSceneBindingCount + 1u;         // GpuVisiblePoint per pixel (written)
const uint kVisiblePointsRasterDirectBinding = kSceneBindingCount + 2u; // vec4 per pixel: raster direct light (--direct raster)

// caustic_estimate.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kCausticEstimateFilmBinding = kSceneBindingCount + 0u;
const uint kCausticEstimatePointBinding = kSceneBindingCount + 1u;
const uint kCausticEstimateGridBinding = kSceneBindingCount + 2u;       // the caustic map's grid (two bindings)

// final_gather.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kFinalGatherFilmBinding = kSceneBindingCount + 0u;
const uint kFinalGatherPointBinding = kSceneBindingCount + 1u;
const uint kFinalGatherGridBinding = kSceneBindingCount + 2u;           // the global map's or the radiance photons' grid (two bindings)
const uint kFinalGatherGuideCellsBinding = kSceneBindingCount + 4u;     // the guiding cache (guide_cache_access.glsl): cells
const uint kFinalGatherGuideCdfsBinding = kSceneBindingCount + 5u;      // and grids
const uint kFinalGatherSampleBinding = kSceneBindingCount + 6u;         // GatherSample per pixel and ray (written with reuse)

// gather_reuse.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kGatherReuseFilmBinding = kSceneBindingCount + 0u;
const uint kGatherReusePointBinding = kSceneBindingCount + 1u;
const uint kGatherReuseSampleBinding = kSceneBindingCount + 2u;         // GatherSample per pixel and ray

// sppm_update.comp: the scene's (0 .. kSceneBindingCount - 1), then
const uint kSppmUpdatePixelBinding = kSceneBindingCount + 0u;            // SppmPixel per pixel
const uint kSppmUpdatePointBinding = kSceneBindingCount + 1u;
const uint kSppmUpdateGridBinding = kSceneBindingCount + 2u;            // this pass's photon map's grid (two bindings)

// radiance_photons.comp
const uint kRadiancePhotonsGridBinding = 0u;        // the global map's grid (0, 1)
const uint kRadiancePhotonsOutputBinding = 2u;      // GpuPhoton per global photon: radiance photons

SHARED_END

#ifdef __cplusplus
#include "shared/photon_render.glsl"
#include "shared/visible_point.glsl"
namespace vkp::gpu {

struct VisiblePointsKernel {
    static constexpr const char* kShader = "visible_points.comp";
    static constexpr uint32_t kBindingCount = kVisiblePointsRasterDirectBinding + 1u;
    static constexpr uint32_t kGroupSize = kPhotonEstimateGroupSize;
    using Push = VisiblePointParams;
};
struct CausticEstimateKernel {
    static constexpr const char* kShader = "caustic_estimate.comp";
    static constexpr uint32_t kBindingCount = kCausticEstimateGridBinding + 2u;
    static constexpr uint32_t kGroupSize = kPhotonEstimateGroupSize;
    using Push = CausticEstimateParams;
};
struct FinalGatherKernel {
    static constexpr const char* kShader = "final_gather.comp";
    static constexpr uint32_t kBindingCount = kFinalGatherSampleBinding + 1u;
    static constexpr uint32_t kGroupSize = kPhotonEstimateGroupSize;
    using Push = FinalGatherParams;
};
struct GatherReuseKernel {
    static constexpr const char* kShader = "gather_reuse.comp";
    static constexpr uint32_t kBindingCount = kGatherReuseSampleBinding + 1u;
    static constexpr uint32_t kGroupSize = kPhotonEstimateGroupSize;
    using Push = GatherReuseParams;
};
struct SppmUpdateKernel {
    static constexpr const char* kShader = "sppm_update.comp";
    static constexpr uint32_t kBindingCount = kSppmUpdateGridBinding + 2u;
    static constexpr uint32_t kGroupSize = kPhotonEstimateGroupSize;
    using Push = SppmParams;
};
struct RadiancePhotonsKernel {
    static constexpr const char* kShader = "radiance_photons.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M photons
    static constexpr uint32_t kBindingCount = kRadiancePhotonsOutputBinding + 1u;
    static constexpr uint32_t kGroupSize = kPhotonEstimateGroupSize;
    using Push = RadiancePhotonParams;
};

}  // namespace vkp::gpu
#endif
#endif
