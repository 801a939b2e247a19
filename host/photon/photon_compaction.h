// Photon compaction pass (shaders/compact_*.comp): reads the photon slots of one traced chunk
// and appends the photons a map keeps to a dense map buffer, in slot order (mark, GPU prefix
// sum, scatter, advance the map's end), so chunks of paths fill one map of millions of photons
// while each chunk's slot buffer stays within the device's storage-buffer range.
#pragma once

#include "passes/prefix_scan.h"
#include "shared/kernels/compaction.glsl"
#include "shared/photon_grid.glsl"
#include "vk/buffer.h"
#include "vk/segmented_buffer.h"
#include "vk/kernel.h"

namespace vkp {

class PhotonCompaction {
public:
    // Chunks of up to `maxSlots` slots of `slots`; `state` holds kPhotonMapStateSize uints
    // (count, dropped), zeroed by the caller before the first chunk. `params.slotCount` is unused.
    // The map is a segmented array (any size); `params.capacity` is replaced by record's.
    PhotonCompaction(vk::Context& context, const vk::Buffer& slots, uint32_t maxSlots, const vk::SegmentedBuffer& map,
                     const vk::Buffer& state, const gpu::PhotonCompactParams& params);

    // Records the append of the first `slotCount` slots to a map that holds `capacity` photons
    // now (its allocated part: photons past it are counted as dropped); the caller places a
    // barrier before (after the slot writes) and after.
    void record(VkCommandBuffer cmd, uint32_t slotCount, uint32_t capacity) const;

    // record() in two submissions, so the map's memory can follow what it keeps: recordCount
    // ranks the kept slots (mark and scan; then keptCount() reads how many after the submission),
    // recordAppend (in a later submission, after the map has room) appends them.
    void recordCount(VkCommandBuffer cmd, uint32_t slotCount) const;
    uint32_t keptCount() const;
    void recordAppend(VkCommandBuffer cmd, uint32_t slotCount, uint32_t capacity) const;

private:
    gpu::PhotonCompactParams m_params;
    uint32_t m_maxSlots;
    vk::Buffer m_ranks;
    PrefixScan m_scan;
    vk::Kernel<gpu::CompactMarkKernel> m_mark;
    vk::Kernel<gpu::CompactScatterKernel> m_scatter;
    vk::Kernel<gpu::CompactAdvanceKernel> m_advance;
};

}  // namespace vkp
