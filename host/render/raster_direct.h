// --direct raster for whichever integrator renders: the raster pass (passes/raster_direct_pass.h)
// run once per frame, its per-pixel direct light, and the kPathFlagRaster* flags that tell the
// camera-path shaders which lights it covers at the first vertex. With --direct traced it only
// supplies a placeholder buffer for the shaders' binding and no flags.
#pragma once

#include <cstdint>
#include <memory>

#include "gpu_scene/gpu_scene.h"
#include "passes/raster_direct_pass.h"
#include "render/frame.h"
#include "lights/light_reach.h"
#include "render/stats.h"

namespace vkp {

class RasterDirectLight {
public:
    // Runs the raster pass (shadow volumes, masks, lighting) when settings.direct is Raster.
    // With `reach` (--light-sampler photon), lights whose primary photons reach no cell the camera
    // sees are left out of the pass (lights/light_reach.h).
    RasterDirectLight(const GpuScene& scene, const FrameSettings& settings, const gpu::GpuCamera& camera,
                      const LightReach* reach = nullptr);

    // The per-pixel direct light (vec4, RGB) of the covered lights, or a placeholder.
    const vk::Buffer& direct() const { return m_pass ? m_pass->direct() : m_placeholder; }
    uint32_t pathFlags() const { return m_flags; }
    // "settings.direct", and with --direct raster "raster.lights", "raster.seconds" and, with
    // photon light cells, "raster.skippedLights" (lights of the scene left out).
    void report(Stats& stats) const;
    double seconds() const { return m_seconds; }

private:
    std::unique_ptr<RasterDirectPass> m_pass;
    vk::Buffer m_placeholder;
    uint32_t m_flags = 0;
    uint64_t m_lights = 0;
    int64_t m_skipped = -1;  // -1: no light reach
    double m_seconds = 0.0;
};

}  // namespace vkp
