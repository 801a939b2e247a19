// A selective photon update's exact change detection (shaders/photon/selective_mark.comp): tests every
// stored path's track against the changed regions and lights, sets the stale paths' bits and
// writes their weights (photon/selective_photon_update.h).
#pragma once

#include "shared/kernels/selective_mark.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"
#include "vk/segmented_buffer.h"

namespace vkp {

class SelectiveMarkPass {
public:
    SelectiveMarkPass(vk::Context& context, const vk::SegmentedBuffer& tracks, const vk::SegmentedBuffer& slots,
                      const vk::Buffer& regions, const vk::Buffer& lights, const vk::Buffer& stale,
                      const vk::Buffer& weights, const vk::Buffer& counters);

    void record(VkCommandBuffer cmd, const gpu::SelectiveMarkParams& params) const;

private:
    vk::Kernel<gpu::SelectiveMarkKernel> m_kernel;
};

}  // namespace vkp
