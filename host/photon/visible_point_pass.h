// Visible-point pass (shaders/photon/visible_points.comp): reads the scene, adds emission and direct
// light at the first non-delta surface to the film, writes one GpuVisiblePoint per pixel.
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "shared/kernels/photon_estimates.glsl"
#include "shared/visible_point.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class VisiblePointPass {
public:
    // `rasterDirect`: the raster pass's direct light (any buffer when the flags do not ask for it).
    VisiblePointPass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                     const vk::Buffer& visiblePoints, const vk::Buffer& rasterDirect);

    // `pixels`: the window of pixels to compute (--tile, --crop), all by default.
    void record(VkCommandBuffer cmd, const gpu::VisiblePointParams& params, vk::ItemRange pixels = {}) const;

private:
    vk::Kernel<gpu::VisiblePointsKernel> m_kernel;
};

}  // namespace vkp
