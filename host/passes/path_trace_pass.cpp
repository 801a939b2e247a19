#include "passes/path_trace_pass.h"

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {
namespace {

// The interface of `shader`, one of the path tracer kernels.
vk::KernelInterface pathTraceInterface(const std::string& shader) {
    for (const vk::KernelInterface& k : {vk::interfaceOf<gpu::PathTraceKernel>(), vk::interfaceOf<gpu::GuidedPathTraceKernel>(),
                                         vk::interfaceOf<gpu::GuidedCachedPathTraceKernel>(),
                                         vk::interfaceOf<gpu::GuidedLearningPathTraceKernel>()})
        if (k.shader == shader) return k;
    throw RuntimeError(fmt::format("{}: not a path tracer kernel (shared/kernels/path_trace.glsl)", shader));
}

}  // namespace

PathTracePass::PathTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                             const vk::Buffer& counters, const vk::Buffer& rasterDirect, const std::string& shader,
                             const std::vector<const vk::Buffer*>& guide)
    : m_kernel(context, pathTraceInterface(shader)) {
    m_kernel.bind(scene.bindings());
    m_kernel.bind(gpu::kPathTraceFilmBinding, film);
    m_kernel.bind(gpu::kPathTraceCounterBinding, counters);
    m_kernel.bind(gpu::kPathTraceRasterDirectBinding, rasterDirect);
    m_kernel.bind(guide, gpu::kPathTraceGuideBinding);
}

void PathTracePass::record(VkCommandBuffer cmd, const gpu::PathTraceParams& params, vk::ItemRange pixels) const {
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, params);
}

void PathTracePass::record(VkCommandBuffer cmd, const gpu::PathTraceParams& params, const gpu::GuideParams& guide,
                           vk::ItemRange pixels) const {
    m_kernel.record(cmd, pixels, uint64_t(params.width) * params.height, gpu::GuidedPathTraceParams{params, guide});
}

PathTraceCounters PathTracePass::readCounters(const vk::Buffer& counters) {
    uint32_t c[gpu::kPathTraceCounterCount];
    counters.download(c, sizeof(c));
    PathTraceCounters out;
    out.nonFiniteSamples = c[gpu::kPathTraceCounterNonFinite];
    out.segments = c[gpu::kPathTraceCounterSegmentsLow] | (uint64_t(c[gpu::kPathTraceCounterSegmentsHigh]) << 32);
    return out;
}

}  // namespace vkp
