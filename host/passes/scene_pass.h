// A compute pass over a 1-D range of items (pixels) that reads the scene buffers at bindings 0..7
// (shaders/scene_access.glsl) and its own buffers from binding 8 on: the photon integrator's
// estimate passes (caustic_estimate.comp, final_gather.comp, sppm_update.comp), each named in
// the comment of its shader.
#pragma once

#include <string>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "vk/buffer.h"
#include "vk/compute_kernel.h"

namespace vkp {

class ScenePass {
public:
    ScenePass(vk::Context& context, std::string shader, const SceneBuffers& scene,
              const std::vector<const vk::Buffer*>& buffers, uint32_t pushBytes);

    template <typename Push> void record(VkCommandBuffer cmd, uint64_t items, const Push& push) const {
        m_kernel.record(cmd, vk::groupCount(items, kGroupSize), push);
    }

private:
    static constexpr uint32_t kGroupSize = 64;  // local_size_x of the pass shaders
    vk::ComputeKernel m_kernel;
};

}  // namespace vkp
