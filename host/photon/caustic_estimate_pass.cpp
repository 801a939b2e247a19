#include "photon/caustic_estimate_pass.h"

namespace vkp {

CausticEstimatePass::CausticEstimatePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                                         const vk::Buffer& visiblePoints, const PhotonGrid& causticGrid)
    : m_kernel(context) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kCausticEstimateFilmBinding, film);
    m_kernel.bind(gpu::kCausticEstimatePointBinding, visiblePoints);
    m_kernel.bind(gpu::kCausticEstimateGridBinding, causticGrid.cellStart());
    m_kernel.bind(gpu::kCausticEstimateGridBinding + 1, causticGrid.photons());
}

void CausticEstimatePass::record(VkCommandBuffer cmd, const gpu::CausticEstimateParams& params, vk::ItemRange pixels) const {
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, params);
}

}  // namespace vkp
