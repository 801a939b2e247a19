#include "photon/sppm_update_pass.h"

namespace vkp {

SppmUpdatePass::SppmUpdatePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& pixels,
                               const vk::Buffer& visiblePoints, const PhotonGrid& grid)
    : m_kernel(context) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kSppmUpdatePixelBinding, pixels);
    m_kernel.bind(gpu::kSppmUpdatePointBinding, visiblePoints);
    m_kernel.bind(gpu::kSppmUpdateGridBinding, grid.cellStart());
    m_kernel.bind(gpu::kSppmUpdateGridBinding + 1, grid.photons());
}

void SppmUpdatePass::record(VkCommandBuffer cmd, const gpu::SppmParams& params, vk::ItemRange pixels) const {
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, params);
}

}  // namespace vkp
