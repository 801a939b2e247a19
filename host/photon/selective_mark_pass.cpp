#include "photon/selective_mark_pass.h"

namespace vkp {

SelectiveMarkPass::SelectiveMarkPass(vk::Context& context, const vk::SegmentedBuffer& tracks,
                                     const vk::SegmentedBuffer& slots, const vk::Buffer& regions,
                                     const vk::Buffer& lights, const vk::Buffer& stale, const vk::Buffer& weights,
                                     const vk::Buffer& counters)
    : m_kernel(context) {
    m_kernel.bind(gpu::kSelectiveMarkTrackBinding, tracks.table());
    m_kernel.bind(gpu::kSelectiveMarkSlotBinding, slots.table());
    m_kernel.bind(gpu::kSelectiveMarkRegionBinding, regions);
    m_kernel.bind(gpu::kSelectiveMarkLightBinding, lights);
    m_kernel.bind(gpu::kSelectiveMarkStaleBinding, stale);
    m_kernel.bind(gpu::kSelectiveMarkWeightBinding, weights);
    m_kernel.bind(gpu::kSelectiveMarkCounterBinding, counters);
}

void SelectiveMarkPass::record(VkCommandBuffer cmd, const gpu::SelectiveMarkParams& params) const {
    m_kernel.record(cmd, params.pathCount, params);
}

}  // namespace vkp
