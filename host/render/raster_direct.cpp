#include "render/raster_direct.h"

#include <algorithm>

#include "passes/raster_lights.h"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace vkp {

RasterDirectLight::RasterDirectLight(const GpuScene& scene, const FrameSettings& settings,
                                     const gpu::GpuCamera& camera, const LightReach* reach) {
    vk::Context& context = scene.context();
    if (settings.direct != DirectLight::Raster) {
        m_placeholder = vk::Buffer(context, "no raster direct", 16, vk::kStorageUsage);
        return;
    }
    // The shadow volumes' projection is a pinhole's (points at infinity need w = 0).
    if (camera.orthoHalfHeight > 0.0f)
        throw InputError("--direct raster: the camera is orthographic; the raster pass needs a perspective camera "
                         "(use --direct traced, or --fov for a pinhole)");
    // The direct light of the covered lights at the first vertex, once per frame (it is
    // deterministic); every sample adds it.
    const auto start = Clock::now();
    std::vector<bool> keep;
    if (reach) {
        keep = lightsReachingView(scene.arrays(), *reach, camera, settings.width, settings.height);
        m_skipped = std::count(keep.begin(), keep.end(), false);
    }
    const auto lights = buildRasterLights(scene.arrays(), settings.areaLightSamples, reach ? &keep : nullptr);
    m_pass = std::make_unique<RasterDirectPass>(context, scene.arrays(), scene.buffers(), lights, settings.width,
                                                settings.height);
    context.submitAndWait(
        [&](VkCommandBuffer cmd) { m_pass->record(cmd, camera, rasterNearPlane(scene.scene().bounds)); });
    m_seconds = secondsSince(start);
    m_lights = lights.size();
    m_flags = gpu::kPathFlagRasterDeltaLights | (settings.areaLightSamples > 0 ? gpu::kPathFlagRasterAreaLights : 0u);
}

void RasterDirectLight::report(Stats& stats) const {
    stats.set("settings.direct", m_pass ? "raster" : "traced");
    if (!m_pass) return;
    stats.set("raster.lights", m_lights);
    stats.set("raster.seconds", m_seconds);
    if (m_skipped >= 0) stats.set("raster.skippedLights", uint64_t(m_skipped));
}

}  // namespace vkp
