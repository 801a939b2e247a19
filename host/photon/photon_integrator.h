// The photon integrator (--integrator photon): Jensen's two-pass method (shared/papers/004) on the
// GPU. prepare() traces the global and caustic photon maps (photon/photon_map.h), after the
// importon pass when deposition is importance-driven. Per camera sample: visible points behind
// delta bounces with emission and next-event direct light (visible_points.comp), caustics from
// the caustic map (caustic_estimate.comp), and indirect light by a final gather into the global
// map (final_gather.comp), whose rays rough surfaces share with their neighbours (gather_reuse.comp).
#pragma once

#include <memory>

#include "gpu_scene/gpu_scene.h"
#include "photon/guide_cache.h"
#include "photon/radiance_photons.h"
#include "photon/caustic_estimate_pass.h"
#include "photon/final_gather_pass.h"
#include "photon/gather_reuse_pass.h"
#include "photon/visible_point_pass.h"
#include "photon/importon_map.h"
#include "render/integrator.h"
#include "render/integrator_registry.h"
#include "photon/photon_settings.h"
#include "photon/photon_map.h"
#include "shared/photon_render.glsl"
#include "vk/stage_timer.h"

namespace vkp {

class PhotonIntegrator : public Integrator {
public:
    // Throws InputError for settings out of range or a scene whose lights emit nothing.
    PhotonIntegrator(const GpuScene& scene, const PhotonIntegratorSettings& settings);

    std::string name() const override { return "photon"; }
    void prepare(const Frame& frame, const Film& film) override;
    uint32_t maxSamplesPerBatch() const override { return 64; }
    void recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) override;
    bool recordsSampleParts() const override { return true; }
    void recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) override;
    std::optional<std::string> stoppedEarly() const override {
        return m_stopReason.empty() ? std::nullopt : std::optional<std::string>(m_stopReason);
    }
    void report(Stats& stats) const override;

private:
    void buildMaps(const Frame& frame);
    // Sample `sample`: visible points and final gathers of `pixels`, caustics of those in the window,
    // and the shared gathers of `shared` (timed: stage queries).
    void recordSample(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange pixels, vk::ItemRange shared, bool timed);
    // The reuse pass's parameters at a sample: the radius shrinks as samples grow (gatherReuseRadius).
    gpu::GatherReuseParams reuseParams(uint32_t sample) const;
    void buildGatherGuide(const PhotonMapStats& globalStats);

    const GpuScene& m_scene;
    PhotonIntegratorSettings m_settings;
    float m_radius;
    Stats m_stats;  // of the last prepare()
    std::unique_ptr<ImportonMap> m_importons;
    std::unique_ptr<PhotonMap> m_globalMap;
    std::unique_ptr<PhotonMap> m_causticMap;
    std::unique_ptr<RadiancePhotons> m_radiancePhotons;
    std::unique_ptr<GuideCache> m_gatherGuide;  // gather directions from the global map's indirect photons
    std::unique_ptr<vk::Buffer> m_points;
    std::unique_ptr<VisiblePointPass> m_visiblePass;
    std::unique_ptr<FinalGatherPass> m_gatherPass;
    std::unique_ptr<CausticEstimatePass> m_causticPass;
    std::unique_ptr<vk::Buffer> m_gatherSamples;  // every gather ray of a sample (--gather-reuse)
    std::unique_ptr<GatherReusePass> m_reusePass;
    std::unique_ptr<vk::StageTimer> m_timer;  // GPU time of the camera passes (kStage*)
    gpu::VisiblePointParams m_visibleParams{};
    gpu::CausticEstimateParams m_causticParams{};
    gpu::FinalGatherParams m_gatherParams{};
    gpu::GatherReuseParams m_reuseParams{};  // radius and window: reuseParams(sample)
    float m_globalCellSize = 0.0f;
    std::string m_stopReason;  // a photon pass stopped early (render/render_control.h)
    vk::ItemRange m_window;    // the pixels the camera passes compute (--tile, --crop)
};

// The radius (in pixel footprints) within which camera sample `sample` shares final gathers:
// radius (1 + sample / kGatherReuseShrinkSamples)^(-1/6), the rate at which a 2-D kernel estimate's
// squared bias and variance shrink together, so that shared gathers converge to the plain ones.
constexpr double kGatherReuseShrinkSamples = 64.0;
float gatherReuseRadius(float radius, uint32_t sample);

// The visible-point pass's parameters for a frame (shared with the progressive integrator).
gpu::VisiblePointParams visiblePointParams(const Frame& frame, uint32_t lightCount);
// Throws InputError when the scene's lights emit no power (no photons to trace).
void requireLightPower(const GpuScene& scene);
// "photons.pathsTraced", "photons.dropped" and "photons.seconds" of one map build, added, and
// the build's stages in "timings.photon.*".
void reportMapBuild(Stats& stats, const PhotonMapStats& map);
// The user's summary of the maps (notes) and a warning for dropped photons, from "photons.*".
void reportPhotonSummary(Stats& stats);

// --integrator photon (the two-pass method) and --integrator sppm (--progressive): one family,
// one config (PhotonIntegratorSettings) and its options.
IntegratorKind photonIntegratorKind();
IntegratorKind sppmIntegratorKind();

}  // namespace vkp
