// Stochastic progressive photon mapping (--integrator sppm, or --progressive; Hachisuka & Jensen
// 2009): every sample is a pass with fresh photons from a new Halton range, new visible points,
// and per-pixel radii that shrink (sppm_update.comp), so the estimate converges to the path
// tracer's answer. The film holds what needs no photons (emission, direct light); finish() adds
// each pixel's photon estimate tau / (passes pi R^2).
#pragma once

#include <memory>

#include "gpu_scene/gpu_scene.h"
#include "photon/sppm_update_pass.h"
#include "photon/visible_point_pass.h"
#include "photon/importon_map.h"
#include "render/integrator.h"
#include "photon/photon_settings.h"
#include "photon/photon_map.h"
#include "shared/photon_render.glsl"

namespace vkp {

class ProgressivePhotonIntegrator : public Integrator {
public:
    // Throws InputError for settings out of range or a scene whose lights emit nothing.
    ProgressivePhotonIntegrator(const GpuScene& scene, const PhotonIntegratorSettings& settings);

    std::string name() const override { return "photon (progressive)"; }
    void prepare(const Frame& frame, const Film& film) override;
    // One pass per submission: each pass first traces its own photon map.
    uint32_t maxSamplesPerBatch() const override { return 1; }
    void beginSamples(uint32_t first, uint32_t count) override;
    void recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) override;
    bool recordsSampleParts() const override { return true; }
    void recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) override;
    bool beginsWithHostWork() const override { return true; }
    void finish(ImageRgb& image, uint32_t samplesDone) override;
    const vk::Buffer* progressiveEstimates() const override { return m_sppm.get(); }
    std::optional<std::string> stoppedEarly() const override {
        return m_stopReason.empty() ? std::nullopt : std::optional<std::string>(m_stopReason);
    }
    void report(Stats& stats) const override;

private:
    const GpuScene& m_scene;
    PhotonIntegratorSettings m_settings;
    float m_radius;
    Stats m_stats;  // of the last frame
    uint64_t m_pixels = 0;
    std::unique_ptr<ImportonMap> m_importons;
    std::unique_ptr<PhotonMap> m_map;
    std::unique_ptr<vk::Buffer> m_points;
    std::unique_ptr<vk::Buffer> m_sppm;
    std::unique_ptr<VisiblePointPass> m_visiblePass;
    std::unique_ptr<SppmUpdatePass> m_updatePass;
    gpu::VisiblePointParams m_visibleParams{};
    gpu::SppmParams m_sppmParams{};
    std::string m_stopReason;  // a photon pass stopped early (render/render_control.h)
    vk::ItemRange m_window;    // the pixels the camera passes compute (--tile, --crop)
};

}  // namespace vkp
