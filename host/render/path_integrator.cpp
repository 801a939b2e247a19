#include "render/path_integrator.h"

#include <algorithm>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace vkp {
namespace {

// Samples per pixel one path-tracing dispatch adds. lavapipe ends every loop of a shader
// invocation once all of them together have run 65535 iterations (docs/photon-mapping.md), and a
// sample costs a few hundred traversal steps: more samples per dispatch would cut paths short.
constexpr uint32_t kMaxSamplesPerDispatch = 8;

}  // namespace

PathSampleRecorder::PathSampleRecorder(const GpuScene& scene, const Frame& frame, const Film& film,
                                       uint32_t samplesPerDispatch, uint32_t extraFlags, const std::string& shader,
                                       const std::vector<const vk::Buffer*>& guide)
    : m_pass(scene.context(), scene.buffers(), film.sums(), film.counters(), *frame.rasterDirect, shader, guide),
      m_samplesPerDispatch(samplesPerDispatch), m_pixels(frame.pixelRange()) {
    m_params.camera = frame.gpuCamera;
    m_params.width = frame.width;
    m_params.height = frame.height;
    m_params.seed = frame.seed;
    m_params.maxDepth = frame.maxDepth;
    m_params.lightCount = scene.buffers().lightCount();
    m_params.flags = (frame.nextEventEstimation ? 0u : gpu::kPathFlagNoDirectLightSampling) |
                     frame.cameraPathFlags() | extraFlags;
}

void PathSampleRecorder::record(VkCommandBuffer cmd, uint32_t first, uint32_t count, const gpu::GuideParams* guide) {
    for (uint32_t done = 0; done < count; done += m_samplesPerDispatch) {
        m_params.firstSample = first + done;
        m_params.sampleCount = std::min(m_samplesPerDispatch, count - done);
        if (guide) m_pass.record(cmd, m_params, *guide, m_pixels);
        else m_pass.record(cmd, m_params, m_pixels);
        vk::computeBarrier(cmd);
    }
}

void PathSampleRecorder::recordPart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part,
                                    const gpu::GuideParams* guide) {
    m_params.firstSample = sample;
    m_params.sampleCount = 1;
    if (guide) m_pass.record(cmd, m_params, *guide, part);
    else m_pass.record(cmd, m_params, part);
    vk::computeBarrier(cmd);
}

void PathIntegrator::prepare(const Frame& frame, const Film& film) {
    m_recorder = std::make_unique<PathSampleRecorder>(m_scene, frame, film, kMaxSamplesPerDispatch, 0u);
}

void PathIntegrator::recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) {
    m_recorder->record(cmd, first, count);
}

IntegratorKind pathIntegratorKind() {
    class Config : public IntegratorConfig {
    public:
        std::unique_ptr<Integrator> create(const GpuScene& scene) const override {
            return std::make_unique<PathIntegrator>(scene);
        }
    };
    return {"path", "path tracing with next-event estimation and MIS, the reference",
            [] { return std::make_unique<Config>(); }};
}

}  // namespace vkp
