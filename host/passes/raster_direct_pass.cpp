#include "passes/raster_direct_pass.h"

#include <algorithm>

#include "vk/context.h"
#include "vk/image.h"

namespace vkp {

RasterDirectPass::RasterDirectPass(vk::Context& context, const SceneArrays& arrays, const SceneBuffers& scene,
                                   const std::vector<gpu::GpuLight>& rasterLights, uint32_t width, uint32_t height,
                                   VolumeGeometry geometry)
    : m_width(width), m_height(height), m_shadows(context, worldTriangles(arrays), rasterLights, width, height, geometry),
      m_direct(context, "raster direct", uint64_t(width) * height * sizeof(glm::vec4), vk::kStorageUsage),
      m_lighting(context),
      m_alphaTested(std::any_of(arrays.triangles.begin(), arrays.triangles.end(),
                                [](const gpu::GpuTriangle& t) { return t.v0.w != 0.0f; })) {
    m_lighting.bind(scene.bindings());
    m_lighting.bind(gpu::kRasterDirectLightBinding, m_shadows.lights());
    m_lighting.bind(gpu::kRasterDirectMaskBinding, m_shadows.masks());
    m_lighting.bind(gpu::kRasterDirectOutputBinding, m_direct);
}

void RasterDirectPass::record(VkCommandBuffer cmd, const gpu::GpuCamera& camera, float near) const {
    m_direct.fillZero(cmd);
    m_shadows.record(cmd, camera, near);
    vk::transferToComputeBarrier(cmd);
    const uint64_t pixels = uint64_t(m_width) * m_height;
    for (uint32_t pass = 0; pass < m_shadows.passCount(); ++pass) {
        gpu::RasterDirectParams params{};
        params.camera = camera;
        params.width = m_width;
        params.height = m_height;
        params.firstLight = pass * gpu::kLightsPerMaskPass;
        params.lightCount = std::min(gpu::kLightsPerMaskPass, m_shadows.lightCount() - params.firstLight);
        params.maskOffset = static_cast<uint32_t>(pass * pixels);
        params.alphaTested = m_alphaTested ? 1u : 0u;
        m_lighting.record(cmd, pixels, params);
        vk::computeBarrier(cmd);  // the next pass adds to the same pixels
    }
}

float rasterNearPlane(const Bounds& bounds) {
    return 1.0e-4f * std::max(1.0e-3f, glm::length(bounds.extent()));
}

}  // namespace vkp
