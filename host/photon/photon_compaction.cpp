#include "photon/photon_compaction.h"

namespace vkp {

PhotonCompaction::PhotonCompaction(vk::Context& context, const vk::Buffer& slots, uint32_t maxSlots,
                                   const vk::SegmentedBuffer& map, const vk::Buffer& state,
                                   const gpu::PhotonCompactParams& params)
    : m_params(params), m_maxSlots(maxSlots),
      m_ranks(context, "photon compaction ranks", (VkDeviceSize(maxSlots) + 1) * sizeof(uint32_t), vk::kStorageUsage),
      m_scan(context, m_ranks, maxSlots + 1),
      m_mark(context), m_scatter(context), m_advance(context) {
    std::vector<const vk::Buffer*> bindings(gpu::kCompactBindingCount);
    bindings[gpu::kCompactSlotBinding] = &slots;
    bindings[gpu::kCompactRankBinding] = &m_ranks;
    bindings[gpu::kCompactMapBinding] = &map.table();
    bindings[gpu::kCompactStateBinding] = &state;
    m_mark.bind(bindings);
    m_scatter.bind(bindings);
    m_advance.bind(bindings);
}

void PhotonCompaction::record(VkCommandBuffer cmd, uint32_t slotCount, uint32_t capacity) const {
    recordCount(cmd, slotCount);
    recordAppend(cmd, slotCount, capacity);
}

void PhotonCompaction::recordCount(VkCommandBuffer cmd, uint32_t slotCount) const {
    gpu::PhotonCompactParams params = m_params;
    params.slotCount = slotCount;
    params.scannedCount = m_maxSlots;
    // Marks cover every scanned entry (zeros past slotCount), so the scan's length is fixed.
    m_mark.record(cmd, uint64_t(m_maxSlots) + 1, params);
    vk::computeBarrier(cmd);
    m_scan.record(cmd);
}

uint32_t PhotonCompaction::keptCount() const {
    uint32_t kept = 0;
    m_ranks.download(&kept, sizeof(kept), VkDeviceSize(m_maxSlots) * sizeof(uint32_t));
    return kept;
}

void PhotonCompaction::recordAppend(VkCommandBuffer cmd, uint32_t slotCount, uint32_t capacity) const {
    gpu::PhotonCompactParams params = m_params;
    params.slotCount = slotCount;
    params.capacity = capacity;
    params.scannedCount = m_maxSlots;
    m_scatter.record(cmd, slotCount, params);
    vk::computeBarrier(cmd);
    m_advance.record(cmd, 1, params);  // one invocation
}

}  // namespace vkp
