// Importance lookup passes: read the importance grid's table and photon slots
// (shaders/photon/importance_lookup.comp) or importon slots (shaders/photon/importon_importance.comp), write
// per slot the importance density and the largest path importance around it (vec2; zeros for
// empty slots and photons the map does not keep).
#pragma once

#include "shared/importance.glsl"
#include "shared/kernels/importons.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

template <typename Kernel> class ImportanceLookupPassOf {
public:
    ImportanceLookupPassOf(vk::Context& context, const vk::Buffer& table, const vk::Buffer& slots,
                           const vk::Buffer& importance)
        : m_kernel(context) {
        m_kernel.bind(gpu::kImportanceLookupTableBinding, table);
        m_kernel.bind(gpu::kImportanceLookupSlotBinding, slots);
        m_kernel.bind(gpu::kImportanceLookupImportanceBinding, importance);
    }

    // Looks up params.slotCount slots.
    void record(VkCommandBuffer cmd, const gpu::ImportanceGridParams& params) const {
        m_kernel.record(cmd, params.slotCount, params);
    }

private:
    vk::Kernel<Kernel> m_kernel;
};

// At photons (deposition).
using ImportanceLookupPass = ImportanceLookupPassOf<gpu::ImportanceLookupKernel>;
// At importons (the scale f of Keller & Wald's deposition probability).
using ImportonImportancePass = ImportanceLookupPassOf<gpu::ImportonImportanceKernel>;

}  // namespace vkp
