// The guided path tracer's guide (--integrator guided): a photon map of the indirect photons
// (direct photons are left out: next-event estimation covers direct light) with grid cells that
// follow its density, and — unless --guide-cache off — the guiding cache built from it. Says
// which path-tracer shader reads it, with which buffers and push constants.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "passes/guide_cache.h"
#include "render/photon_map.h"
#include "render/renderer.h"

namespace vkp {

// Throws InputError for settings the guided path tracer cannot use.
void checkGuideSettings(const GuideRenderSettings& settings);

class PathGuide {
public:
    PathGuide(vk::Context& context, const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers,
              const GuideRenderSettings& settings, uint32_t seed);

    const std::string& shader() const { return m_shader; }
    std::vector<const vk::Buffer*> buffers() const;
    const gpu::GuideParams& params() const { return m_params; }
    const PhotonMap& map() const { return *m_map; }
    // Largest search radius of a k-nearest gather in the map.
    float searchRadius() const { return m_searchRadius; }
    // Photon counts, bytes and seconds into the render's statistics.
    void addStats(RenderStats& stats) const;

private:
    std::unique_ptr<PhotonMap> m_map;
    std::unique_ptr<GuideCache> m_cache;
    gpu::GuideParams m_params{};
    PhotonMapStats m_mapStats;
    double m_seconds = 0.0;
    float m_searchRadius = 0.0f;
    std::string m_shader;
};

}  // namespace vkp
