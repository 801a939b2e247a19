#include "photon/photon_deposit.h"

#include <algorithm>

#include <glm/glm.hpp>

#include "vk/context.h"

namespace vkp {

PhotonDeposit::PhotonDeposit(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& importanceTable,
                             const vk::Buffer& slots, uint32_t maxSlots, const vk::SegmentedBuffer& map,
                             const PhotonGrid& mapGrid, uint32_t segmentShift)
    : m_importance(context, "deposit importance", std::max<VkDeviceSize>(16, VkDeviceSize(maxSlots) * sizeof(glm::vec2)),
                   vk::kStorageUsage),
      // Indexed 3 i + channel in 32 bits: PhotonMap keeps density-controlled maps within that.
      m_redistributed(context, "deposit redistributed power", sizeof(uint32_t),
                      std::max<uint64_t>(3, 3 * uint64_t(mapGrid.capacity())), segmentShift),
      m_lookup(context, importanceTable, slots, m_importance), m_deposit(context), m_redistribute(context) {
    m_deposit.bind(scene.bindings());
    m_deposit.bind(gpu::kPhotonDepositGridBinding, mapGrid.cellStart());
    m_deposit.bind(gpu::kPhotonDepositGridBinding + 1, mapGrid.photons());
    m_deposit.bind(gpu::kPhotonDepositSlotBinding, slots);
    m_deposit.bind(gpu::kPhotonDepositImportanceBinding, m_importance);
    m_deposit.bind(gpu::kPhotonDepositRedistributedBinding, m_redistributed.table());
    m_redistribute.bind(gpu::kRedistributeMapBinding, map.table());
    m_redistribute.bind(gpu::kRedistributeSortedSlotBinding, mapGrid.sortedSlots());
    m_redistribute.bind(gpu::kRedistributeRedistributedBinding, m_redistributed.table());
}

void PhotonDeposit::reserve(uint64_t gridPhotons) { m_redistributed.reserve(3 * gridPhotons); }

void PhotonDeposit::recordClear(VkCommandBuffer cmd) const { m_redistributed.fillZero(cmd); }

void PhotonDeposit::recordRedistribution(VkCommandBuffer cmd, uint32_t gridPhotons) const {
    gpu::RedistributeParams params{};
    params.gridPhotons = gridPhotons;
    m_redistribute.record(cmd, gridPhotons, params);
}

void PhotonDeposit::record(VkCommandBuffer cmd, gpu::ImportanceGridParams lookup,
                           const gpu::PhotonDepositParams& params) const {
    lookup.slotCount = params.slotCount;
    m_lookup.record(cmd, lookup);
    vk::computeBarrier(cmd);
    m_deposit.record(cmd, params.slotCount, params);
}

}  // namespace vkp
