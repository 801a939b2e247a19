// Final gather pass (shaders/photon/final_gather.comp): reads the scene, the visible points and a photon
// grid (the global map's, or the radiance photons'), adds one gather ray's share of the indirect
// light to each pixel's film entry (vec4: RGB sum, sample count). With a guiding cache
// (photon/guide_cache.h) over the global map's indirect photons, gather directions are
// importance-sampled from it, mixed with the BSDF's. With params.reuse, pixels whose BSDF is rough
// leave their rays in `gatherSamples` (gpu::GatherSample per pixel and ray) for GatherReusePass.
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "photon/guide_cache.h"
#include "photon/photon_grid.h"
#include "shared/kernels/photon_estimates.glsl"
#include "shared/photon_render.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class FinalGatherPass {
public:
    // `guide` (may be null): the guiding cache the gather directions are importance-sampled from
    // (params.guide.mix > 0); without one, params.guide.mix must be 0.
    // `gatherSamples` (may be null): written with params.reuse, which needs it.
    FinalGatherPass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                    const vk::Buffer& visiblePoints, const PhotonGrid& grid, const GuideCache* guide = nullptr,
                    const vk::Buffer* gatherSamples = nullptr);

    // One dispatch over params.width * params.height pixels (one gather ray: params.rayIndex).
    // `pixels`: the window of pixels to compute (--tile, --crop), all by default.
    void record(VkCommandBuffer cmd, const gpu::FinalGatherParams& params, vk::ItemRange pixels = {}) const;

private:
    vk::Kernel<gpu::FinalGatherKernel> m_kernel;
    vk::Buffer m_unused;  // bound in the cache's or the samples' place when there is none (never used)
    bool m_guided;
    bool m_reusable;
};

}  // namespace vkp
