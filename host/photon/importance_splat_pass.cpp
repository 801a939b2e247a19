#include "photon/importance_splat_pass.h"

namespace vkp {

ImportanceSplatPass::ImportanceSplatPass(vk::Context& context, const vk::Buffer& importons, const vk::Buffer& table)
    : m_kernel(context) {
    m_kernel.bind(gpu::kImportanceSplatImportonBinding, importons);
    m_kernel.bind(gpu::kImportanceSplatTableBinding, table);
}

void ImportanceSplatPass::record(VkCommandBuffer cmd, const gpu::ImportanceGridParams& params) const {
    m_kernel.record(cmd, params.slotCount, params);
}

}  // namespace vkp
