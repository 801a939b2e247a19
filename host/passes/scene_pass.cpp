#include "passes/scene_pass.h"

namespace vkp {
namespace {
constexpr uint32_t kFirstPassBinding = 8;  // after the scene's eight buffers
}

ScenePass::ScenePass(vk::Context& context, std::string shader, const SceneBuffers& scene,
                     const std::vector<const vk::Buffer*>& buffers, uint32_t pushBytes)
    : m_kernel(context, std::move(shader), kFirstPassBinding + static_cast<uint32_t>(buffers.size()), pushBytes) {
    m_kernel.bind(scene.bindings());
    for (uint32_t i = 0; i < buffers.size(); ++i) m_kernel.bind(kFirstPassBinding + i, *buffers[i]);
}

}  // namespace vkp
