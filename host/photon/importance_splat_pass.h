// Importance splat pass (shaders/photon/importance_splat.comp): reads the importon slots, adds every
// importon to its cell of the importance grid's table at every level (shared/importance.glsl).
#pragma once

#include "shared/importance.glsl"
#include "shared/kernels/importons.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class ImportanceSplatPass {
public:
    // `table`: ImportanceCell entries (a power of two of them), zeroed by the caller before.
    ImportanceSplatPass(vk::Context& context, const vk::Buffer& importons, const vk::Buffer& table);

    // Splats params.slotCount slots into a table of params.tableMask + 1 entries.
    void record(VkCommandBuffer cmd, const gpu::ImportanceGridParams& params) const;

private:
    vk::Kernel<gpu::ImportanceSplatKernel> m_kernel;
};

}  // namespace vkp
