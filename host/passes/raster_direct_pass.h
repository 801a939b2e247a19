// Raster direct light (Dmitriev et al. 2002, section 6.1): the shadow-volume mask passes
// (shadow_volume_pass.h) followed per pass by the lighting pass (shaders/raster/raster_direct.comp),
// which adds each light's BSDF-weighted contribution times its mask channel at the pixel centre's
// visible point. Reads the scene buffers; writes `direct()` (vec4 per pixel, RGB radiance), the
// first-vertex direct light of every raster-covered light for the path tracer to add to each sample.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "passes/shadow_volume_pass.h"
#include "shared/kernels/raster_direct.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class RasterDirectPass {
public:
    RasterDirectPass(vk::Context& context, const SceneArrays& arrays, const SceneBuffers& scene,
                     const std::vector<gpu::GpuLight>& rasterLights, uint32_t width, uint32_t height,
                     VolumeGeometry geometry = VolumeGeometry::Compute);

    // Clears the direct buffer, records the mask passes and the lighting passes; ends with the
    // direct buffer visible to compute shaders.
    void record(VkCommandBuffer cmd, const gpu::GpuCamera& camera, float near) const;

    const vk::Buffer& direct() const { return m_direct; }
    const ShadowVolumePass& shadows() const { return m_shadows; }

private:
    uint32_t m_width;
    uint32_t m_height;
    ShadowVolumePass m_shadows;
    vk::Buffer m_direct;
    vk::Kernel<gpu::RasterDirectKernel> m_lighting;
    bool m_alphaTested;  // the scene has MASK/BLEND triangles (RasterDirectParams::alphaTested)
};

// Near plane distance of the raster camera: small against the scene so nothing in view is clipped.
float rasterNearPlane(const Bounds& bounds);

}  // namespace vkp
