#include "render/raster_direct.h"

#include "passes/raster_lights.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace vkp {

RasterDirectLight::RasterDirectLight(vk::Context& context, const Scene& scene, const SceneArrays& arrays,
                                     const SceneBuffers& buffers, const RenderSettings& settings) {
    if (settings.direct != DirectLight::Raster) {
        m_placeholder = vk::Buffer(context, "no raster direct", 16, vk::kStorageUsage);
        return;
    }
    // The direct light of the covered lights at the first vertex, once per frame (it is
    // deterministic); every sample adds it.
    const auto lights = buildRasterLights(arrays, settings.areaLightSamples);
    m_pass = std::make_unique<RasterDirectPass>(context, arrays, buffers, lights, settings.width, settings.height);
    const gpu::GpuCamera camera =
        makeGpuCamera(chooseCamera(scene, settings.cameraIndex), settings.width, settings.height);
    const auto start = Clock::now();
    context.submitAndWait([&](VkCommandBuffer cmd) { m_pass->record(cmd, camera, rasterNearPlane(scene.bounds)); });
    m_seconds = secondsSince(start);
    m_lights = lights.size();
    m_flags = gpu::kPathFlagRasterDeltaLights | (settings.areaLightSamples > 0 ? gpu::kPathFlagRasterAreaLights : 0u);
}

void RasterDirectLight::addStats(RenderStats& stats) const {
    stats.direct = m_pass ? "raster" : "traced";
    stats.rasterLights = m_lights;
    stats.rasterSeconds = m_seconds;
}

}  // namespace vkp
