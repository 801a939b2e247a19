#include "passes/photon_deposit.h"

#include <glm/glm.hpp>

#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {

PhotonDeposit::PhotonDeposit(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& importanceTable,
                             const vk::Buffer& slots, uint32_t maxSlots, const vk::Buffer& map,
                             const PhotonGrid& mapGrid)
    : m_importance(context, "deposit importance", std::max<VkDeviceSize>(16, VkDeviceSize(maxSlots) * sizeof(glm::vec2)),
                   vk::kStorageUsage),
      m_redistributed(context, "deposit redistributed power",
                      std::max<VkDeviceSize>(16, VkDeviceSize(mapGrid.slotCount()) * 3 * sizeof(uint32_t)),
                      vk::kStorageUsage),
      m_lookup(context, "importance_lookup.comp", 3, sizeof(gpu::ImportanceGridParams)),
      m_deposit(context, "photon_deposit.comp", scene,
                {&mapGrid.cellStart(), &mapGrid.photons(), &slots, &m_importance, &m_redistributed},
                sizeof(gpu::PhotonDepositParams)),
      m_redistribute(context, "deposit_redistribute.comp", 3, sizeof(gpu::RedistributeParams)) {
    m_lookup.bind({&importanceTable, &slots, &m_importance});
    m_redistribute.bind({&map, &mapGrid.sortedSlots(), &m_redistributed});
    context.submitAndWait([&](VkCommandBuffer cmd) { m_redistributed.fillZero(cmd); });
}

void PhotonDeposit::recordRedistribution(VkCommandBuffer cmd, uint32_t gridPhotons) const {
    gpu::RedistributeParams params{};
    params.gridPhotons = gridPhotons;
    m_redistribute.record(cmd, vk::groupCount(gridPhotons, 64), params);
}

void PhotonDeposit::record(VkCommandBuffer cmd, gpu::ImportanceGridParams lookup,
                           const gpu::PhotonDepositParams& params) const {
    lookup.slotCount = params.slotCount;
    m_lookup.record(cmd, vk::groupCount(params.slotCount, 64), lookup);
    vk::computeBarrier(cmd);
    m_deposit.record(cmd, params.slotCount, params);
}

}  // namespace vkp
