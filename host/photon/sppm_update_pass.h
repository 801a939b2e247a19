// SPPM update pass (shaders/photon/sppm_update.comp): reads the scene, the visible points and one photon
// pass's map grid, updates each pixel's progressive statistics (SppmPixel: flux, photon count,
// radius; Hachisuka & Jensen 2009) in place.
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "photon/photon_grid.h"
#include "shared/kernels/photon_estimates.glsl"
#include "shared/photon_render.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class SppmUpdatePass {
public:
    SppmUpdatePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& pixels,
                   const vk::Buffer& visiblePoints, const PhotonGrid& grid);

    // One dispatch over params.width * params.height pixels.
    // `pixels`: the window of pixels to compute (--tile, --crop), all by default.
    void record(VkCommandBuffer cmd, const gpu::SppmParams& params, vk::ItemRange pixels = {}) const;

private:
    vk::Kernel<gpu::SppmUpdateKernel> m_kernel;
};

}  // namespace vkp
