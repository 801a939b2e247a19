#include "guiding/guide_learning.h"

#include <algorithm>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "vk/context.h"

namespace vkp {
namespace {

// Samples per pixel drawn from the photons' grids alone before the first update.
constexpr uint32_t kFirstIteration = 8;

uint32_t gridCountOf(const GuideCache& cache) {
    return static_cast<uint32_t>(cache.cdfs().size() / (gpu::kMaxGuideCells * sizeof(float)));
}

}  // namespace

GuideLearning::GuideLearning(vk::Context& context, const GuideCache& cache, double meanRadiance)
    : m_gridCount(gridCountOf(cache)), m_gridSize(cache.params().gridSize),
      m_scale(meanRadiance > 0.0 ? static_cast<float>(gpu::kGuideLearnFixedPoint / meanRadiance) : gpu::kGuideLearnFixedPoint),
      m_prior(context, "guide learning prior", cache.cdfs().size(), vk::kStorageUsage),
      m_sums(context, "guide learning sums",
             sizeof(glm::vec4) + VkDeviceSize(m_gridCount) * gpu::kGuideLearnStride * sizeof(glm::uvec2), vk::kStorageUsage),
      m_update(context) {
    context.submitAndWait([&](VkCommandBuffer cmd) {
        vk::transferBarrier(cmd);
        const VkBufferCopy region{0, 0, cache.cdfs().size()};
        vkCmdCopyBuffer(cmd, cache.cdfs().handle(), m_prior.handle(), 1, &region);
    });
    m_update.bind(gpu::kGuideLearnPriorBinding, m_prior);
    m_update.bind(gpu::kGuideLearnIrradianceBinding, cache.irradiance());
    m_update.bind(gpu::kGuideLearnSumsBinding, m_sums);
    m_update.bind(gpu::kGuideLearnCdfsBinding, cache.cdfs());
}

bool GuideLearning::iterationStartsAt(uint32_t sample) {
    return sample >= kFirstIteration && sample % kFirstIteration == 0 && ((sample / kFirstIteration) & (sample / kFirstIteration - 1)) == 0;
}

uint32_t GuideLearning::nextIterationStart(uint32_t sample) {
    uint64_t start = kFirstIteration;
    while (start <= sample) start *= 2;
    return static_cast<uint32_t>(std::min<uint64_t>(start, UINT32_MAX));
}

void GuideLearning::recordBefore(VkCommandBuffer cmd, uint32_t sample) const {
    if (sample == 0) record(cmd, true);
    else if (iterationStartsAt(sample)) record(cmd, false);
}

void GuideLearning::record(VkCommandBuffer cmd, bool reset) const {
    vk::computeBarrier(cmd);  // the samples before have written the sums and read the CDFs
    m_update.record(cmd, m_gridCount, gpu::GuideLearnParams{m_gridCount, m_gridSize, reset ? 1u : 0u, m_scale});
    vk::computeBarrier(cmd);
}

}  // namespace vkp
