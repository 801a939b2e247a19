#include "photon/importon_trace_pass.h"

namespace vkp {

ImportonTracePass::ImportonTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& importons)
    : m_kernel(context) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kImportonTraceImportonBinding, importons);
}

void ImportonTracePass::record(VkCommandBuffer cmd, const gpu::ImportonTraceParams& params) const {
    m_kernel.record(cmd, params.pathCount, params);
}

}  // namespace vkp
