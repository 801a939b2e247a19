// Importance lookup pass (shaders/importance_lookup.comp): reads the importance grid's table and
// photon (or importon) slots, writes per slot the importance density and the largest path
// importance around it (vec2; zeros for empty slots and photons the map does not keep).
#pragma once

#include "shared/importance.glsl"
#include "shared/kernels/importons.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class ImportanceLookupPass {
public:
    ImportanceLookupPass(vk::Context& context, const vk::Buffer& table, const vk::Buffer& slots,
                         const vk::Buffer& importance);

    // Looks up params.slotCount slots.
    void record(VkCommandBuffer cmd, const gpu::ImportanceGridParams& params) const;

private:
    vk::Kernel<gpu::ImportanceLookupKernel> m_kernel;
};

}  // namespace vkp
