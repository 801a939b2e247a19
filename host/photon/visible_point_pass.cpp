#include "photon/visible_point_pass.h"

namespace vkp {

VisiblePointPass::VisiblePointPass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                                   const vk::Buffer& visiblePoints, const vk::Buffer& rasterDirect)
    : m_kernel(context) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kVisiblePointsFilmBinding, film);
    m_kernel.bind(gpu::kVisiblePointsPointBinding, visiblePoints);
    m_kernel.bind(gpu::kVisiblePointsRasterDirectBinding, rasterDirect);
}

void VisiblePointPass::record(VkCommandBuffer cmd, const gpu::VisiblePointParams& params, vk::ItemRange pixels) const {
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, params);
}

}  // namespace vkp
