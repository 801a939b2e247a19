#include "passes/photon_deposit.h"

#include <glm/glm.hpp>

#include "vk/compute_kernel.h"

namespace vkp {

PhotonDeposit::PhotonDeposit(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& importanceTable,
                             const vk::Buffer& slots, uint32_t maxSlots, const PhotonGrid& map)
    : m_importance(context, "deposit importance", std::max<VkDeviceSize>(16, VkDeviceSize(maxSlots) * sizeof(glm::vec2)),
                   vk::kStorageUsage),
      m_lookup(context, "importance_lookup.comp", 3, sizeof(gpu::ImportanceGridParams)),
      m_deposit(context, "photon_deposit.comp", scene, {&map.cellStart(), &map.photons(), &slots, &m_importance},
                sizeof(gpu::PhotonDepositParams)) {
    m_lookup.bind({&importanceTable, &slots, &m_importance});
}

void PhotonDeposit::record(VkCommandBuffer cmd, gpu::ImportanceGridParams lookup,
                           const gpu::PhotonDepositParams& params) const {
    lookup.slotCount = params.slotCount;
    m_lookup.record(cmd, vk::groupCount(params.slotCount, 64), lookup);
    vk::computeBarrier(cmd);
    m_deposit.record(cmd, params.slotCount, params);
}

}  // namespace vkp
