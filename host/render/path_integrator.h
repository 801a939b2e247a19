// The path tracer (--integrator path, the reference): next-event estimation and BSDF sampling
// combined by MIS, Russian roulette, path regeneration (shaders/render/path_tracer.glsl). The guided
// path tracer (guided_integrator.h) records its samples the same way, with a guide bound.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gpu_scene/gpu_scene.h"
#include "passes/path_trace_pass.h"
#include "render/integrator.h"
#include "render/integrator_registry.h"

namespace vkp {

// Records path-tracing samples in dispatches small enough for lavapipe's loop budget.
class PathSampleRecorder {
public:
    // `samplesPerDispatch`: samples per pixel one dispatch adds (docs/photon-mapping.md).
    PathSampleRecorder(const GpuScene& scene, const Frame& frame, const Film& film, uint32_t samplesPerDispatch,
                       uint32_t extraFlags, const std::string& shader = "pathtrace.comp",
                       const std::vector<const vk::Buffer*>& guide = {});

    // Records samples [first, first + count) with the guide's push constants when there is one.
    void record(VkCommandBuffer cmd, uint32_t first, uint32_t count, const gpu::GuideParams* guide = nullptr);
    // Records sample `sample` of the pixels in `part` only (Integrator::recordSamplePart).
    void recordPart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part, const gpu::GuideParams* guide = nullptr);

private:
    PathTracePass m_pass;
    gpu::PathTraceParams m_params{};
    uint32_t m_samplesPerDispatch;
    vk::ItemRange m_pixels;  // the frame's window (--tile, --crop)
};

class PathIntegrator : public Integrator {
public:
    explicit PathIntegrator(const GpuScene& scene) : m_scene(scene) {}

    std::string name() const override { return "path"; }
    void prepare(const Frame& frame, const Film& film) override;
    uint32_t maxSamplesPerBatch() const override { return 4096; }
    void recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) override;
    bool recordsSampleParts() const override { return true; }
    void recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) override {
        m_recorder->recordPart(cmd, sample, part);
    }
    void report(Stats& stats) const override { (void)stats; }

private:
    const GpuScene& m_scene;
    std::unique_ptr<PathSampleRecorder> m_recorder;
};

// --integrator path: no options of its own (--max-depth and --no-nee belong to the frame).
IntegratorKind pathIntegratorKind();

}  // namespace vkp
