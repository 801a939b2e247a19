#include "photon/final_gather_pass.h"

#include <stdexcept>

namespace vkp {

FinalGatherPass::FinalGatherPass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                                 const vk::Buffer& visiblePoints, const PhotonGrid& grid, const GuideCache* guide,
                                 const vk::Buffer* gatherSamples)
    : m_kernel(context), m_guided(guide != nullptr), m_reusable(gatherSamples != nullptr) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kFinalGatherFilmBinding, film);
    m_kernel.bind(gpu::kFinalGatherPointBinding, visiblePoints);
    m_kernel.bind(gpu::kFinalGatherGridBinding, grid.cellStart());
    m_kernel.bind(gpu::kFinalGatherGridBinding + 1, grid.photons());
    if (!guide || !gatherSamples) m_unused = vk::Buffer(context, "unused final-gather binding", 16, vk::kStorageUsage);
    m_kernel.bind(gpu::kFinalGatherGuideCellsBinding, guide ? guide->cells() : m_unused);
    m_kernel.bind(gpu::kFinalGatherGuideCdfsBinding, guide ? guide->cdfs() : m_unused);
    m_kernel.bind(gpu::kFinalGatherSampleBinding, gatherSamples ? *gatherSamples : m_unused);
}

void FinalGatherPass::record(VkCommandBuffer cmd, const gpu::FinalGatherParams& params, vk::ItemRange pixels) const {
    if (params.guide.mix > 0.0f && !m_guided) throw std::logic_error("FinalGatherPass: guided gathers without a guiding cache");
    if (params.reuse != 0 && !m_reusable) throw std::logic_error("FinalGatherPass: shared gathers without a gather-sample buffer");
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, params);
}

}  // namespace vkp
