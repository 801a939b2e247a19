// The driver: resolves the frame (camera, raster direct light), owns the film and runs the
// sample loop (batches sized towards a target time, progress, the time limit, Ctrl-C) for any
// integrator behind render/integrator.h, then collects the statistics.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>

#include "gpu_scene/gpu_scene.h"
#include "lights/light_cells.h"
#include "image/image.h"
#include "render/frame.h"
#include "render/integrator.h"
#include "render/stats.h"

namespace vkp {

struct RenderResult {
    ImageRgb image;
    // Keys (docs/architecture.md): "integrator", "device", "stopReason", "partial",
    // "counters.samplesPerPixel", "counters.cameraPaths", "counters.nonFiniteSamples",
    // "counters.pathSegments", "timings.renderSeconds", "settings.*", "scene_stats.*", and
    // whatever the integrator reports (e.g. "photons.*").
    Stats stats;
};

class Renderer {
public:
    // Builds the BVH and uploads the scene once for every render that follows, with next-event
    // estimation choosing and sampling lights by `lightSampling`.
    Renderer(vk::Context& context, const Scene& scene, LightSampling lightSampling = {});

    const GpuScene& gpuScene() const { return m_scene; }
    // --light-sampler photon: traces the light cells' photons again in the scene as it is now
    // (after in-place motion: GpuScene::updateInstanceTransforms, updatePunctualLights) and
    // replaces the cells and the light reach. Returns false when the cells no longer fit the
    // light-selection buffer: integrators built before must then be built again. Other samplers:
    // nothing to do (true).
    bool refreshLightCells();
    const std::optional<LightCellStats>& lightCells() const { return m_lightCells; }
    const std::optional<LightReach>& lightReach() const { return m_lightReach; }
    // For per-frame instance motion (GpuScene::updateInstanceTransforms) between renders.
    GpuScene& gpuScene() { return m_scene; }

    // Renders one frame with `integrator` (built for gpuScene()). `stop` (may be null) ends the
    // render after the current batch; the image then holds the samples accumulated so far.
    RenderResult render(const FrameSettings& settings, Integrator& integrator, const ProgressCallback& progress = {},
                        const std::atomic<bool>* stop = nullptr);

    // Builds an integrator of type I for this scene from `args` and renders with it.
    template <typename I, typename... Args> RenderResult render(const FrameSettings& settings, Args&&... args) {
        I integrator(m_scene, std::forward<Args>(args)...);
        return render(settings, integrator);
    }

private:
    GpuScene m_scene;
    LightSampling m_lightSampling;
    std::optional<LightCellStats> m_lightCells;  // --light-sampler photon
    std::optional<LightReach> m_lightReach;      // --light-sampler photon: for --direct raster
};

}  // namespace vkp
