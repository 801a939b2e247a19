#include "photon/photon_trace_pass.h"

namespace vkp {

PhotonTracePass::PhotonTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& photons,
                                 const vk::Buffer& counters, const vk::Buffer& pathList, const vk::Buffer& tracks)
    : m_kernel(context) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kPhotonTracePhotonBinding, photons);
    m_kernel.bind(gpu::kPhotonTraceCounterBinding, counters);
    m_kernel.bind(gpu::kPhotonTracePathListBinding, pathList);
    m_kernel.bind(gpu::kPhotonTraceTrackBinding, tracks);
}

void PhotonTracePass::record(VkCommandBuffer cmd, const gpu::PhotonTraceParams& params) const {
    m_kernel.record(cmd, params.pathCount, params);
}

}  // namespace vkp
