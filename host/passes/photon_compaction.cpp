#include "passes/photon_compaction.h"

namespace vkp {

PhotonCompaction::PhotonCompaction(vk::Context& context, const vk::Buffer& slots, uint32_t maxSlots,
                                   const vk::Buffer& map, const vk::Buffer& state,
                                   const gpu::PhotonCompactParams& params)
    : m_params(params), m_maxSlots(maxSlots),
      m_ranks(context, "photon compaction ranks", (VkDeviceSize(maxSlots) + 1) * sizeof(uint32_t), vk::kStorageUsage),
      m_scan(context, m_ranks, maxSlots + 1),
      m_mark(context, "compact_mark.comp", 4, sizeof(gpu::PhotonCompactParams)),
      m_scatter(context, "compact_scatter.comp", 4, sizeof(gpu::PhotonCompactParams)),
      m_advance(context, "compact_advance.comp", 4, sizeof(gpu::PhotonCompactParams)) {
    const std::vector<const vk::Buffer*> bindings{&slots, &m_ranks, &map, &state};
    m_mark.bind(bindings);
    m_scatter.bind(bindings);
    m_advance.bind(bindings);
}

void PhotonCompaction::record(VkCommandBuffer cmd, uint32_t slotCount) const {
    gpu::PhotonCompactParams params = m_params;
    params.slotCount = slotCount;
    params.scannedCount = m_maxSlots;
    // Marks cover every scanned entry (zeros past slotCount), so the scan's length is fixed.
    m_mark.record(cmd, vk::groupCount(uint64_t(m_maxSlots) + 1, gpu::kGridGroupSize), params);
    vk::computeBarrier(cmd);
    m_scan.record(cmd);
    m_scatter.record(cmd, vk::groupCount(slotCount, gpu::kGridGroupSize), params);
    vk::computeBarrier(cmd);
    m_advance.record(cmd, 1, params);
}

}  // namespace vkp
