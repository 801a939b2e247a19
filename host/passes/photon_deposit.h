// Importance-driven deposition of one traced chunk of photon slots (docs/importance-deposition.md):
// importance_lookup.comp senses the importons around every photon, photon_deposit.comp keeps
// or drops each photon (and reweights the kept ones) in place, before the map's compaction.
#pragma once

#include "passes/photon_grid.h"
#include "passes/scene_pass.h"
#include "shared/importance.glsl"
#include "vk/buffer.h"

namespace vkp {

class PhotonDeposit {
public:
    // Bound to the chunk's `slots` (up to maxSlots), the importance grid's table
    // (shared/importance.glsl) and the map's own grid (read by density control).
    PhotonDeposit(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& importanceTable,
                  const vk::Buffer& slots, uint32_t maxSlots, const PhotonGrid& map);

    // Records the lookup and the decision for params.slotCount slots (lookup.slotCount is set
    // from it); the caller places a barrier before (after the slot writes) and after.
    void record(VkCommandBuffer cmd, gpu::ImportanceGridParams lookup, const gpu::PhotonDepositParams& params) const;

    uint64_t bytes() const { return m_importance.size(); }

private:
    vk::Buffer m_importance;  // per slot: importance density, largest path importance
    vk::ComputeKernel m_lookup;
    ScenePass m_deposit;
};

}  // namespace vkp
