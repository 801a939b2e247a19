// Caustic estimate pass (shaders/photon/caustic_estimate.comp): reads the scene, the visible points and
// the caustic map's grid, adds each pixel's caustic radiance to its film entry (vec4: RGB sum,
// sample count).
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "photon/photon_grid.h"
#include "shared/kernels/photon_estimates.glsl"
#include "shared/photon_render.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class CausticEstimatePass {
public:
    CausticEstimatePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                        const vk::Buffer& visiblePoints, const PhotonGrid& causticGrid);

    // One dispatch over params.width * params.height pixels.
    // `pixels`: the window of pixels to compute (--tile, --crop), all by default.
    void record(VkCommandBuffer cmd, const gpu::CausticEstimateParams& params, vk::ItemRange pixels = {}) const;

private:
    vk::Kernel<gpu::CausticEstimateKernel> m_kernel;
};

}  // namespace vkp
