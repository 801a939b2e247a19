#include "photon/final_gather_pass.h"

namespace vkp {

FinalGatherPass::FinalGatherPass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                                 const vk::Buffer& visiblePoints, const PhotonGrid& grid)
    : m_kernel(context) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kFinalGatherFilmBinding, film);
    m_kernel.bind(gpu::kFinalGatherPointBinding, visiblePoints);
    m_kernel.bind(gpu::kFinalGatherGridBinding, grid.cellStart());
    m_kernel.bind(gpu::kFinalGatherGridBinding + 1, grid.photons());
}

void FinalGatherPass::record(VkCommandBuffer cmd, const gpu::FinalGatherParams& params, vk::ItemRange pixels) const {
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, params);
}

}  // namespace vkp
