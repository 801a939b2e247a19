// The guided path tracer's guide (--integrator guided): a photon map of the indirect photons
// (direct photons are left out: next-event estimation covers direct light) with grid cells that
// follow its density, and — unless --guide-cache off — the guiding cache built from it. Says
// which path-tracer shader reads it, with which buffers and push constants.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gpu_scene/gpu_scene.h"
#include "guiding/guide_learning.h"
#include "photon/guide_cache.h"
#include "photon/photon_map.h"
#include "render/stats.h"

namespace CLI { class App; }

namespace vkp {

// Settings of the guide (--integrator guided, `vkphoton guide-grid`).
struct GuideSettings {
    uint32_t photons = 100000;        // --guide-photons: paths traced for the guiding map
    uint32_t k = 50;                  // --guide-k nearest photons per grid
    uint32_t gridU = 4;               // --guide-grid MxN: m bands of theta ...
    uint32_t gridV = 16;              // ... by n sectors of phi (m * n <= 64)
    float mix = 0.5f;                 // --guide-mix: probability of sampling the grid (1: the paper's method)
    bool cache = true;                // --guide-cache: grids per cache cell and normal bin, built once
    uint32_t adaptPhotons = 0;        // --guide-adapt: coarsen cache grids to this many photons per cell (0: off)
    bool roulette = false;            // --guide-rr: Russian roulette by the guide's irradiance estimate
    bool learn = true;                // --guide-learn: refine the cache's grids from the path tracer's samples

    // Throws InputError naming the flag of a value the guided path tracer cannot use.
    void check() const;
    // Registers --guide-photons, --guide-k and --guide-grid, and with `sampling` also --guide-mix,
    // --guide-cache, --guide-adapt, --guide-rr and --guide-learn, in `group`, writing into this object.
    void addOptions(CLI::App& group, bool sampling = true);
    // "settings.guide.*".
    void report(Stats& stats) const;
};

class PathGuide {
public:
    // Traces the guiding map (and builds the cache) for runs of `seed`.
    // `control` (may be null) stops the guiding map's tracing between chunks (render_control.h).
    PathGuide(const GpuScene& scene, const GuideSettings& settings, uint32_t seed, const RenderControl* control = nullptr);
    const std::string& stopReason() const { return m_mapStats.stopReason; }

    const std::string& shader() const { return m_shader; }
    std::vector<const vk::Buffer*> buffers() const;
    const gpu::GuideParams& params() const { return m_params; }
    const PhotonMap& map() const { return *m_map; }
    // The cache's learning from the samples (--guide-learn on with the cache), or null.
    const GuideLearning* learning() const { return m_learning.get(); }
    // Largest search radius of a k-nearest gather in the map.
    float searchRadius() const { return m_searchRadius; }
    // "photons.*": photon counts, bytes and seconds; "settings.guide.searchRadius".
    void report(Stats& stats) const;

private:
    std::unique_ptr<PhotonMap> m_map;
    std::unique_ptr<GuideCache> m_cache;
    std::unique_ptr<GuideLearning> m_learning;
    gpu::GuideParams m_params{};
    PhotonMapStats m_mapStats;
    double m_seconds = 0.0;
    float m_searchRadius = 0.0f;
    std::string m_shader;
};

}  // namespace vkp
