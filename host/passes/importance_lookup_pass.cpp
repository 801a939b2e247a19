#include "passes/importance_lookup_pass.h"

namespace vkp {

ImportanceLookupPass::ImportanceLookupPass(vk::Context& context, const vk::Buffer& table, const vk::Buffer& slots,
                                           const vk::Buffer& importance)
    : m_kernel(context) {
    m_kernel.bind(gpu::kImportanceLookupTableBinding, table);
    m_kernel.bind(gpu::kImportanceLookupSlotBinding, slots);
    m_kernel.bind(gpu::kImportanceLookupImportanceBinding, importance);
}

void ImportanceLookupPass::record(VkCommandBuffer cmd, const gpu::ImportanceGridParams& params) const {
    m_kernel.record(cmd, params.slotCount, params);
}

}  // namespace vkp
