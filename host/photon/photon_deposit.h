// Importance-driven deposition of one traced chunk of photon slots (docs/importance-deposition.md):
// importance_lookup.comp senses the importons around every photon, photon_deposit.comp keeps
// or drops each photon (and reweights the kept ones) in place, before the map's compaction;
// density control's deposit_redistribute.comp adds rejected photons' power to the map's photons.
// Reads the scene, the importance grid, the map's grid; writes the chunk's slots and the map.
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "photon/importance_lookup_pass.h"
#include "photon/photon_grid.h"
#include "shared/importance.glsl"
#include "shared/kernels/deposit.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"
#include "vk/segmented_buffer.h"

namespace vkp {

class PhotonDeposit {
public:
    // Bound to the chunk's `slots` (up to maxSlots), the importance grid's table
    // (shared/importance.glsl), the dense map's photons and the grid over them (read by density
    // control, which also hands rejected photons' power to the map's photons). The power handed
    // on is a segmented array (3 words a photon, in segments of 2^segmentShift words; 0: the
    // default), allocated by reserve().
    PhotonDeposit(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& importanceTable,
                  const vk::Buffer& slots, uint32_t maxSlots, const vk::SegmentedBuffer& map, const PhotonGrid& mapGrid,
                  uint32_t segmentShift = 0);

    // Density control with redistribution: room to hand power to the grid's first `gridPhotons`
    // photons (call it as the map grows, outside a recording; new room is zeroed).
    void reserve(uint64_t gridPhotons);

    // Zeroes the power handed to the map's photons (a transfer): record it once, before the first
    // record(), followed by a transfer-to-compute barrier.
    void recordClear(VkCommandBuffer cmd) const;

    // Records the lookup and the decision for params.slotCount slots (lookup.slotCount is set
    // from it); the caller places a barrier before (after the slot writes) and after.
    void record(VkCommandBuffer cmd, gpu::ImportanceGridParams lookup, const gpu::PhotonDepositParams& params) const;

    // Density control with redistribution, after record(): adds the power handed to the grid's
    // `gridPhotons` photons to them in the map (and zeroes it again). Barriers as for record().
    void recordRedistribution(VkCommandBuffer cmd, uint32_t gridPhotons) const;

    uint64_t bytes() const { return m_importance.size() + m_redistributed.bytes(); }
    uint64_t redistributionBytes() const { return m_redistributed.bytes(); }  // grows with the map

private:
    vk::Buffer m_importance;     // per slot: importance density, largest path importance
    vk::SegmentedBuffer m_redistributed;  // per grid photon, rgb: power handed to it (fixed point), zero between rounds
    ImportanceLookupPass m_lookup;
    vk::Kernel<gpu::PhotonDepositKernel> m_deposit;
    vk::Kernel<gpu::DepositRedistributeKernel> m_redistribute;
};

}  // namespace vkp
