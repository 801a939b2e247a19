#include "passes/visible_point_pass.h"

namespace vkp {
namespace {
constexpr uint32_t kFilmBinding = 8;
constexpr uint32_t kVisiblePointBinding = 9;
constexpr uint32_t kRasterDirectBinding = 10;
constexpr uint32_t kGroupSize = 64;  // local_size_x of visible_points.comp
}  // namespace

VisiblePointPass::VisiblePointPass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                                   const vk::Buffer& visiblePoints, const vk::Buffer& rasterDirect)
    : m_kernel(context, "visible_points.comp", kRasterDirectBinding + 1, sizeof(gpu::VisiblePointParams)) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(kFilmBinding, film);
    m_kernel.bind(kVisiblePointBinding, visiblePoints);
    m_kernel.bind(kRasterDirectBinding, rasterDirect);
}

void VisiblePointPass::record(VkCommandBuffer cmd, const gpu::VisiblePointParams& params) const {
    m_kernel.record(cmd, vk::groupCount(uint64_t(params.width) * params.height, kGroupSize), params);
}

}  // namespace vkp
