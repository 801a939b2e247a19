#include "photon/gather_reuse_pass.h"

namespace vkp {

GatherReusePass::GatherReusePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                                 const vk::Buffer& visiblePoints, const vk::Buffer& gatherSamples)
    : m_kernel(context) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kGatherReuseFilmBinding, film);
    m_kernel.bind(gpu::kGatherReusePointBinding, visiblePoints);
    m_kernel.bind(gpu::kGatherReuseSampleBinding, gatherSamples);
}

void GatherReusePass::record(VkCommandBuffer cmd, const gpu::GatherReuseParams& params, vk::ItemRange pixels) const {
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, params);
}

}  // namespace vkp
