#include "passes/scene_pass.h"

#include <fmt/format.h>

#include "shared/kernels/photon_estimates.glsl"
#include "util/errors.h"

namespace vkp {
namespace {

vk::KernelInterface estimateInterface(const std::string& shader, size_t ownBuffers, uint32_t pushBytes) {
    for (const vk::KernelInterface& k : {vk::interfaceOf<gpu::FinalGatherKernel>(), vk::interfaceOf<gpu::CausticEstimateKernel>(),
                                         vk::interfaceOf<gpu::SppmUpdateKernel>()}) {
        if (k.shader != shader) continue;
        if (gpu::kSceneBindingCount + ownBuffers != k.bindingCount || pushBytes != k.pushBytes)
            throw RuntimeError(fmt::format("{}: {} buffers after the scene's and {} bytes of push constants, expected {} and {}",
                                           shader, ownBuffers, pushBytes, k.bindingCount - gpu::kSceneBindingCount,
                                           k.pushBytes));
        return k;
    }
    throw RuntimeError(fmt::format("{}: not an estimate pass (shared/kernels/photon_estimates.glsl)", shader));
}

}  // namespace

ScenePass::ScenePass(vk::Context& context, std::string shader, const SceneBuffers& scene,
                     const std::vector<const vk::Buffer*>& buffers, uint32_t pushBytes)
    : m_kernel(context, estimateInterface(shader, buffers.size(), pushBytes)) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(buffers, gpu::kSceneBindingCount);
}

}  // namespace vkp
