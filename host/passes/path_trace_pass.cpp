#include "passes/path_trace_pass.h"

#include "shared/constants.glsl"

namespace vkp {

namespace {
constexpr uint32_t kFilmBinding = 8;
constexpr uint32_t kCounterBinding = 9;
constexpr uint32_t kRasterDirectBinding = 10;
constexpr uint32_t kGuideBinding = 11;  // the guide's buffers (path_tracer.glsl)

struct GuidedPush {
    gpu::PathTraceParams params;
    gpu::GuideParams guide;
};
static_assert(sizeof(GuidedPush) == 128, "within the guaranteed 128 bytes of push constants");
}  // namespace

PathTracePass::PathTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                             const vk::Buffer& counters, const vk::Buffer& rasterDirect, const std::string& shader,
                             const std::vector<const vk::Buffer*>& guide)
    : m_kernel(context, shader, kGuideBinding + static_cast<uint32_t>(guide.size()),
               guide.empty() ? sizeof(gpu::PathTraceParams) : sizeof(GuidedPush)) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(kFilmBinding, film);
    m_kernel.bind(kCounterBinding, counters);
    m_kernel.bind(kRasterDirectBinding, rasterDirect);
    for (uint32_t i = 0; i < guide.size(); ++i) m_kernel.bind(kGuideBinding + i, *guide[i]);
}

void PathTracePass::record(VkCommandBuffer cmd, const gpu::PathTraceParams& params) const {
    const uint64_t pixels = uint64_t(params.width) * params.height;
    m_kernel.record(cmd, vk::groupCount(pixels, gpu::kPathTraceGroupSize), params);
}

void PathTracePass::record(VkCommandBuffer cmd, const gpu::PathTraceParams& params,
                           const gpu::GuideParams& guide) const {
    const uint64_t pixels = uint64_t(params.width) * params.height;
    m_kernel.record(cmd, vk::groupCount(pixels, gpu::kPathTraceGroupSize), GuidedPush{params, guide});
}

}  // namespace vkp
