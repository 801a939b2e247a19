// Deprecated: host/render/photon_integrator.cpp's estimate passes until it switches to
// FinalGatherPass, CausticEstimatePass and SppmUpdatePass (final_gather_pass.h,
// caustic_estimate_pass.h, sppm_update_pass.h); remove this file then. A compute pass over a 1-D
// range of items (pixels) that reads the scene buffers and its own buffers after them, with the
// interface shared/kernels/photon_estimates.glsl declares for `shader`.
#pragma once

#include <string>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "vk/buffer.h"
#include "vk/compute_kernel.h"

namespace vkp {

class ScenePass {
public:
    // `shader`: final_gather.comp, caustic_estimate.comp or sppm_update.comp; `buffers` bound from
    // the first binding after the scene's on; `pushBytes` must be the interface's.
    ScenePass(vk::Context& context, std::string shader, const SceneBuffers& scene,
              const std::vector<const vk::Buffer*>& buffers, uint32_t pushBytes);

    template <typename Push> void record(VkCommandBuffer cmd, uint64_t items, const Push& push) const {
        m_kernel.record(cmd, vk::groupCount(items, m_kernel.groupSize()), push);
    }

private:
    vk::ComputeKernel m_kernel;
};

}  // namespace vkp
