#include "guiding/guided_integrator.h"

#include <algorithm>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace vkp {
namespace {

// A guided vertex adds to lavapipe's loop budget of a dispatch (docs/photon-mapping.md): with
// the cache a binary search of at most 6 steps over the grid read in place, so as many samples
// per dispatch as the path tracer; without it a k-nearest gather and the grid's construction, so
// one. A budget cut short is not only a darker sample: which samples lavapipe cuts varies from
// run to run (a furnace's per-vertex render, 2 samples per dispatch, lost 0 to 2 samples and its
// mean by 2e-4 between runs of one seed).
constexpr uint32_t kMaxGuidedSamplesPerDispatch = 8;
constexpr uint32_t kMaxPerVertexGuidedSamplesPerDispatch = 1;

}  // namespace

GuidedIntegrator::GuidedIntegrator(const GpuScene& scene, const GuideSettings& settings)
    : m_scene(scene), m_settings(settings) {
    m_settings.check();
}

void GuidedIntegrator::prepare(const Frame& frame, const Film& film) {
    m_guide = std::make_unique<PathGuide>(m_scene, m_settings, frame.seed, &frame.control);
    m_stopReason = m_guide->stopReason();
    m_firstPixel = frame.pixelRange().first;
    m_recorder = std::make_unique<PathSampleRecorder>(
        m_scene, frame, film, m_settings.cache ? kMaxGuidedSamplesPerDispatch : kMaxPerVertexGuidedSamplesPerDispatch,
        m_settings.roulette ? gpu::kPathFlagGuideRoulette : 0u,
        m_guide->shader(), m_guide->buffers());
}

// With learning, the samples of one iteration (guide_learning.h) go in dispatches of their own,
// the grids updated before each iteration's first.
void GuidedIntegrator::recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) {
    const GuideLearning* learning = m_guide->learning();
    for (uint32_t sample = first; sample < first + count;) {
        const uint32_t end = learning ? std::min(first + count, GuideLearning::nextIterationStart(sample)) : first + count;
        if (learning) learning->recordBefore(cmd, sample);
        m_recorder->record(cmd, sample, end - sample, &m_guide->params());
        sample = end;
    }
}

void GuidedIntegrator::recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) {
    if (const GuideLearning* learning = m_guide->learning(); learning && part.first == m_firstPixel)
        learning->recordBefore(cmd, sample);
    m_recorder->recordPart(cmd, sample, part, &m_guide->params());
}

void GuidedIntegrator::report(Stats& stats) const {
    m_settings.report(stats);
    if (m_guide) m_guide->report(stats);
}

IntegratorKind guidedIntegratorKind() {
    class Config : public IntegratorConfig {
    public:
        void addOptions(IntegratorOptions& options) override {
            m_settings.addOptions(options.group("guided path tracer", {"guided"}));
        }
        void check() const override { m_settings.check(); }
        std::string startMessage(const FrameSettings&) const override {
            return fmt::format("tracing {} guiding photon paths ...", m_settings.photons);
        }
        std::unique_ptr<Integrator> create(const GpuScene& scene) const override {
            return std::make_unique<GuidedIntegrator>(scene, m_settings);
        }

    private:
        GuideSettings m_settings;
    };
    return {"guided", "photon-guided path tracing, Jensen 1995", [] { return std::make_unique<Config>(); }};
}

}  // namespace vkp
