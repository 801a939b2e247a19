#include "passes/path_trace_pass.h"

#include "shared/constants.glsl"

namespace vkp {

namespace {
constexpr uint32_t kFilmBinding = 8;
constexpr uint32_t kCounterBinding = 9;
constexpr uint32_t kRasterDirectBinding = 10;
}  // namespace

PathTracePass::PathTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                             const vk::Buffer& counters, const vk::Buffer& rasterDirect)
    : m_kernel(context, "pathtrace.comp", kRasterDirectBinding + 1, sizeof(gpu::PathTraceParams)) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(kFilmBinding, film);
    m_kernel.bind(kCounterBinding, counters);
    m_kernel.bind(kRasterDirectBinding, rasterDirect);
}

void PathTracePass::record(VkCommandBuffer cmd, const gpu::PathTraceParams& params) const {
    const uint64_t pixels = uint64_t(params.width) * params.height;
    m_kernel.record(cmd, vk::groupCount(pixels, gpu::kPathTraceGroupSize), params);
}

}  // namespace vkp
