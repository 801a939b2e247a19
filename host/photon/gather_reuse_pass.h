// Gathers shared between pixels (shaders/photon/gather_reuse.comp): after a camera sample's final
// gathers left their rays in the gather-sample buffer, each pixel whose BSDF is rough adds the mean
// of its own and its neighbours' rays, weighted by its own BSDF, to its film entry.
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "shared/kernels/photon_estimates.glsl"
#include "shared/photon_render.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class GatherReusePass {
public:
    GatherReusePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                    const vk::Buffer& visiblePoints, const vk::Buffer& gatherSamples);

    // One dispatch over the pixels of `pixels` (of params.width * params.height).
    void record(VkCommandBuffer cmd, const gpu::GatherReuseParams& params, vk::ItemRange pixels = {}) const;

private:
    vk::Kernel<gpu::GatherReuseKernel> m_kernel;
};

}  // namespace vkp
