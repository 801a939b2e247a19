// Raster shadow pass (Dmitriev et al. 2002, section 6.1): a depth pre-pass of the scene from the
// camera, then per light z-fail stencil shadow volumes (Carmack's reverse, two-sided stencil,
// volumes extruded to infinity under a reversed infinite projection), and the
// paper's RGBA shadow mask: the stencil result of up to four lights lands in the four channels of
// one mask per pass, ceil(N/4) passes for N lights. Reads the scene triangles and the raster light
// list; writes `masks()`: per pass and pixel one RGBA8 word (a channel is 255 where the light is
// unoccluded), pass p at uint offset p * width * height.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "passes/shadow_triangles.h"
#include "shared/gpu_types.glsl"
#include "shared/kernels/raster_direct.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"
#include "vk/graphics_pipeline.h"
#include "vk/image.h"

namespace vkp {

// World (homogeneous) to clip space for the compute camera's pixel grid: pixel centres land on the
// camera rays of shaders/render/camera_and_lights.glsl. Reversed infinite depth: depth = near / view depth,
// so points at infinity (w = 0) get depth 0 and floats keep their precision far away.
glm::mat4 rasterViewProjection(const gpu::GpuCamera& camera, float near);

// Where the volume geometry is generated (docs/benchmarks.md measures both on lavapipe).
enum class VolumeGeometry {
    Compute,         // shadow_volume_build.comp writes volume triangles, drawn as a vertex buffer
    GeometryShader,  // shadow_volume.geom extrudes the scene drawn with triangle adjacency.
                     // Benchmark only: on lavapipe its masks differ from the compute variant's
                     // along extruded edges (27 % of the pairs in the open-mesh test scene;
                     // cause not found), so the renderer and the tests use Compute.
};

class ShadowVolumePass {
public:
    ShadowVolumePass(vk::Context& context, const std::vector<gpu::GpuTriangle>& triangles,
                     const std::vector<gpu::GpuLight>& rasterLights, uint32_t width, uint32_t height,
                     VolumeGeometry geometry = VolumeGeometry::Compute);

    // Records every mask pass; `near` is the near plane distance (world units). Ends with the
    // masks visible to compute shaders.
    void record(VkCommandBuffer cmd, const gpu::GpuCamera& camera, float near) const;

    const vk::Buffer& masks() const { return m_masks; }
    const vk::Buffer& lights() const { return m_lights; }
    uint32_t lightCount() const { return m_lightCount; }
    uint32_t passCount() const { return m_passCount; }
    const ShadowTriangles& shadowTriangles() const { return m_shadowTriangles; }
    VolumeGeometry geometry() const { return m_geometry; }

private:
    vk::Context& m_context;
    uint32_t m_width;
    uint32_t m_height;
    uint32_t m_triangleCount;
    uint32_t m_lightCount;
    uint32_t m_passCount;
    VolumeGeometry m_geometry;
    std::vector<glm::vec4> m_lightPoints;  // homogeneous light points (geometry-shader push constants)
    ShadowTriangles m_shadowTriangles;
    VkFormat m_depthFormat;
    vk::Image m_depth;
    vk::Image m_mask;
    vk::Buffer m_positions;   // vertex buffer of the pre-pass: 3 x vec4 (w = 1) per triangle, then
                              // one "no neighbour" marker (w = 0) for the adjacency indices
    vk::Buffer m_depthPositions;  // the pre-pass's positions again, two-sided triangles first, then
                                  // m_culledCount whose back faces camera rays skip (GpuTriangle v2.w)
    uint32_t m_culledCount;
    vk::Buffer m_adjacency;   // geometry-shader variant: 6 indices per triangle (with adjacency)
    vk::Buffer m_triangles;   // GpuShadowTriangle per triangle
    vk::Buffer m_lights;      // GpuLight per raster light
    vk::Buffer m_volumes;     // volume vertices of one pass (written by compute, drawn as vertices)
    vk::Buffer m_masks;
    vk::Kernel<gpu::ShadowVolumeBuildKernel> m_build;
    std::unique_ptr<vk::GraphicsPipeline> m_depthPipeline;
    std::unique_ptr<vk::GraphicsPipeline> m_depthCullPipeline;  // the same with back faces culled
    std::unique_ptr<vk::GraphicsPipeline> m_volumePipeline;
    std::unique_ptr<vk::GraphicsPipeline> m_volumeGeometryPipeline;
    std::unique_ptr<vk::GraphicsPipeline> m_maskPipelines[gpu::kLightsPerMaskPass];
};

}  // namespace vkp
