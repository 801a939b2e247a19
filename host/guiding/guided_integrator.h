// The photon-guided path tracer (--integrator guided; Jensen 1995, docs/guided-path-tracing.md):
// prepare() traces the guiding photon map and builds the guiding cache (guiding/path_guide.h);
// samples are the path tracer's with directions drawn from the grid-BSDF mixture.
#pragma once

#include <memory>

#include "render/integrator.h"
#include "render/integrator_registry.h"
#include "render/path_integrator.h"
#include "guiding/path_guide.h"

namespace vkp {

class GuidedIntegrator : public Integrator {
public:
    // Throws InputError for settings out of range.
    GuidedIntegrator(const GpuScene& scene, const GuideSettings& settings);

    std::string name() const override { return "guided"; }
    void prepare(const Frame& frame, const Film& film) override;
    uint32_t maxSamplesPerBatch() const override { return 4096; }
    void recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) override;
    bool recordsSampleParts() const override { return true; }
    void recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) override;
    std::optional<std::string> stoppedEarly() const override {
        return m_stopReason.empty() ? std::nullopt : std::optional<std::string>(m_stopReason);
    }
    void report(Stats& stats) const override;

    const PathGuide& guide() const { return *m_guide; }

private:
    const GpuScene& m_scene;
    GuideSettings m_settings;
    std::unique_ptr<PathGuide> m_guide;
    std::unique_ptr<PathSampleRecorder> m_recorder;
    std::string m_stopReason;  // a photon pass stopped early (render/render_control.h)
    uint64_t m_firstPixel = 0;  // the frame's window's first pixel: a sample's first part starts there
};

// --integrator guided and its "guided path tracer" options.
IntegratorKind guidedIntegratorKind();

}  // namespace vkp
