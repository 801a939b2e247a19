#include "passes/photon_trace_pass.h"

namespace vkp {
namespace {
constexpr uint32_t kPhotonBinding = 8;
constexpr uint32_t kCounterBinding = 9;
constexpr uint32_t kGroupSize = 64;  // local_size_x of photon_trace.comp
}  // namespace

PhotonTracePass::PhotonTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& photons,
                                 const vk::Buffer& counters)
    : m_kernel(context, "photon_trace.comp", kCounterBinding + 1, sizeof(gpu::PhotonTraceParams)) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(kPhotonBinding, photons);
    m_kernel.bind(kCounterBinding, counters);
}

void PhotonTracePass::record(VkCommandBuffer cmd, const gpu::PhotonTraceParams& params) const {
    m_kernel.record(cmd, vk::groupCount(params.pathCount, kGroupSize), params);
}

}  // namespace vkp
