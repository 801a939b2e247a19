#include "passes/shadow_volume_pass.h"

#include <algorithm>

#include "util/errors.h"
#include "vk/context.h"

namespace vkp {
namespace {

constexpr VkFormat kMaskFormat = VK_FORMAT_R8G8B8A8_UNORM;

// The scene as the raster pass sees it: alpha-tested triangles (glTF MASK/BLEND, v0.w != 0, whose
// cut-outs only the traced rays see) collapsed to a point, so they neither write depth nor cast
// shadow volumes; shaders/raster/raster_direct.comp traces shadow rays where they matter.
std::vector<gpu::GpuTriangle> opaqueTriangles(std::vector<gpu::GpuTriangle> triangles) {
    for (gpu::GpuTriangle& t : triangles)
        if (t.v0.w != 0.0f) t.v1 = t.v2 = t.v0;
    return triangles;
}

std::vector<glm::vec4> prepassPositions(const std::vector<gpu::GpuShadowTriangle>& tris) {
    std::vector<glm::vec4> out;
    out.reserve(tris.size() * 3 + 1);
    for (const auto& t : tris) {
        out.push_back(t.v0);
        out.push_back(t.v1);
        out.push_back(t.v2);
    }
    out.push_back(glm::vec4(0.0f));  // the "no neighbour" marker of open triangles
    return out;
}

// The pre-pass's depth triangles: first those both of whose faces camera rays see, then the
// single-sided opaque ones (GpuTriangle v2.w != 0), drawn with back faces culled so the depth is
// that of the surface camera rays meet (docs/scene-format.md "Back faces"). Same positions, same
// vertex order as prepassPositions(), so the shadow volumes' front caps meet the same depths.
std::vector<glm::vec4> depthPositions(const std::vector<gpu::GpuShadowTriangle>& tris,
                                      const std::vector<gpu::GpuTriangle>& triangles, uint32_t& culled) {
    std::vector<glm::vec4> out;
    out.reserve(tris.size() * 3 + 1);
    culled = 0;
    for (const bool cull : {false, true})
        for (size_t t = 0; t < tris.size(); ++t) {
            if ((triangles[t].v2.w != 0.0f) != cull) continue;
            out.push_back(tris[t].v0);
            out.push_back(tris[t].v1);
            out.push_back(tris[t].v2);
            if (cull) ++culled;
        }
    out.push_back(glm::vec4(0.0f));
    return out;
}

// Triangle-list-with-adjacency indices into prepassPositions(): per triangle v0, far vertex of the
// neighbour across v0v1, v1, across v1v2, v2, across v2v0.
std::vector<uint32_t> adjacencyIndices(const std::vector<gpu::GpuShadowTriangle>& tris) {
    const uint32_t marker = static_cast<uint32_t>(tris.size() * 3);
    std::vector<uint32_t> out;
    out.reserve(tris.size() * 6);
    for (uint32_t t = 0; t < tris.size(); ++t) {
        const auto& s = tris[t];
        const glm::vec3 v[3] = {glm::vec3(s.v0), glm::vec3(s.v1), glm::vec3(s.v2)};
        const uint32_t nb[3] = {s.neighbor0, s.neighbor1, s.neighbor2};
        for (uint32_t e = 0; e < 3; ++e) {
            out.push_back(3 * t + e);
            uint32_t far = marker;
            if (s.closed && nb[e] != gpu::kShadowNoNeighbor) {
                const auto& n = tris[nb[e]];
                const glm::vec3 w[3] = {glm::vec3(n.v0), glm::vec3(n.v1), glm::vec3(n.v2)};
                for (uint32_t k = 0; k < 3; ++k)
                    if (w[k] != v[e] && w[k] != v[(e + 1) % 3]) far = 3 * nb[e] + k;
            }
            out.push_back(far);
        }
    }
    return out;
}

glm::vec4 lightPoint(const gpu::GpuLight& light) {
    if (light.type == gpu::kLightDirectional) return glm::vec4(-light.direction, 0.0f);
    return glm::vec4(light.position, 1.0f);
}

VkStencilOpState stencilOp(VkStencilOp fail, VkStencilOp pass, VkStencilOp depthFail, VkCompareOp compare) {
    VkStencilOpState s{};
    s.failOp = fail;
    s.passOp = pass;
    s.depthFailOp = depthFail;
    s.compareOp = compare;
    s.compareMask = 0xff;
    s.writeMask = 0xff;
    s.reference = 0;
    return s;
}

}  // namespace

glm::mat4 rasterViewProjection(const gpu::GpuCamera& c, float near) {
    // Row i of the matrix maps (p, w) to a_i . p + b_i w; view coordinates are taken relative to
    // the camera position scaled by w, so vertices at infinity (w = 0) are pure directions.
    const float sx = 1.0f / (c.aspect * c.tanHalfFovY);
    const float sy = 1.0f / c.tanHalfFovY;
    const glm::vec3 a[4] = {c.right * sx, -c.up * sy, glm::vec3(0.0f), c.forward};
    const float b[4] = {-glm::dot(c.right, c.position) * sx, glm::dot(c.up, c.position) * sy, near,
                        -glm::dot(c.forward, c.position)};
    glm::mat4 m(0.0f);
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 3; ++col) m[col][row] = a[row][col];
        m[3][row] = b[row];
    }
    return m;
}

ShadowVolumePass::ShadowVolumePass(vk::Context& context, const std::vector<gpu::GpuTriangle>& triangles,
                                   const std::vector<gpu::GpuLight>& rasterLights, uint32_t width,
                                   uint32_t height, VolumeGeometry geometry)
    : m_context(context), m_width(width), m_height(height),
      m_triangleCount(static_cast<uint32_t>(triangles.size())),
      m_lightCount(static_cast<uint32_t>(rasterLights.size())),
      m_passCount((m_lightCount + gpu::kLightsPerMaskPass - 1) / gpu::kLightsPerMaskPass),
      m_geometry(geometry),
      m_shadowTriangles(buildShadowTriangles(opaqueTriangles(triangles))),
      m_depthFormat(vk::pickDepthStencilFormat(context)),
      m_depth(context, "raster depth-stencil", width, height, m_depthFormat,
              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
              VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT),
      m_mask(context, "shadow mask", width, height, kMaskFormat,
             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT),
      m_positions(context, "raster positions", (triangles.size() * 3 + 1) * sizeof(glm::vec4),
                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT),
      m_depthPositions(context, "raster depth positions", (triangles.size() * 3 + 1) * sizeof(glm::vec4),
                       VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT),
      m_culledCount(0),
      m_adjacency(context, "adjacency indices", std::max<VkDeviceSize>(16, triangles.size() * 6 * sizeof(uint32_t)),
                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT),
      m_triangles(vk::makeStorageBuffer(context, "shadow triangles", m_shadowTriangles.triangles)),
      m_lights(vk::makeStorageBuffer(context, "raster lights", rasterLights)),
      m_volumes(context, "shadow volumes",
                std::max<VkDeviceSize>(16, VkDeviceSize(m_triangleCount) * gpu::kLightsPerMaskPass *
                                               gpu::kVolumeVerticesPerTriangle * sizeof(glm::vec4)),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT),
      m_masks(context, "shadow masks",
              std::max<VkDeviceSize>(16, VkDeviceSize(std::max(1u, m_passCount)) * width * height * 4),
              vk::kStorageUsage),
      m_build(context) {
    m_positions.upload(prepassPositions(m_shadowTriangles.triangles));
    m_depthPositions.upload(depthPositions(m_shadowTriangles.triangles, triangles, m_culledCount));
    if (m_triangleCount > 0) m_adjacency.upload(adjacencyIndices(m_shadowTriangles.triangles));
    for (const auto& light : rasterLights) m_lightPoints.push_back(lightPoint(light));
    m_build.bind(gpu::kShadowVolumeTriangleBinding, m_triangles);
    m_build.bind(gpu::kShadowVolumeLightBinding, m_lights);
    m_build.bind(gpu::kShadowVolumeVertexBinding, m_volumes);

    vk::GraphicsPipelineDesc base;
    base.vertexShader = "raster_position.vert";
    base.vertexStride = sizeof(glm::vec4);
    base.colorFormat = kMaskFormat;
    base.depthStencilFormat = m_depthFormat;
    base.pushConstantBytes = sizeof(gpu::RasterParams);
    base.depthCompare = VK_COMPARE_OP_GREATER;  // reversed depth: nearer is larger

    vk::GraphicsPipelineDesc depth = base;
    depth.depthTest = true;
    depth.depthWrite = true;
    depth.cullMode = VK_CULL_MODE_NONE;  // both sides of every surface are visible and shade
    m_depthPipeline = std::make_unique<vk::GraphicsPipeline>(context, depth);
    // Single-sided opaque triangles: camera rays skip their back faces. Front faces are
    // counter-clockwise, as for the volumes' two-sided stencil below.
    depth.cullMode = VK_CULL_MODE_BACK_BIT;
    m_depthCullPipeline = std::make_unique<vk::GraphicsPipeline>(context, depth);

    // z-fail ("Carmack's reverse"): count the volume faces *behind* the visible surface, back
    // faces up, front faces down, both in one draw with two-sided stencil. The count is the number
    // of volumes containing the visible point whatever the camera position, because every volume
    // is closed (both caps) and nothing is clipped at infinity: under the reversed infinite
    // projection a w = 0 vertex has clip z = 0, inside 0 <= z <= w. No depth clamp: with it the
    // near plane goes, and NVIDIA's driver (580) then rasterises volume faces behind the camera,
    // counting every pixel as shadowed when the camera is inside a volume (lavapipe clips them).
    vk::GraphicsPipelineDesc volume = base;
    volume.depthTest = true;
    volume.stencilTest = true;
    volume.stencilFront = stencilOp(VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_DECREMENT_AND_WRAP, VK_COMPARE_OP_ALWAYS);
    volume.stencilBack = stencilOp(VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_INCREMENT_AND_WRAP, VK_COMPARE_OP_ALWAYS);
    m_volumePipeline = std::make_unique<vk::GraphicsPipeline>(context, volume);
    if (geometry == VolumeGeometry::GeometryShader) {
        vk::GraphicsPipelineDesc gs = volume;
        gs.vertexShader = "shadow_volume_adj.vert";
        gs.geometryShader = "shadow_volume.geom";
        gs.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY;
        gs.pushConstantBytes = sizeof(gpu::RasterVolumeParams);
        m_volumeGeometryPipeline = std::make_unique<vk::GraphicsPipeline>(context, gs);
    }

    // Mask writer of channel k: lit (count 0) pixels get 1 in channel k; the others fail the
    // stencil test and have their count reset to 0, ready for the next light without a clear.
    for (uint32_t k = 0; k < gpu::kLightsPerMaskPass; ++k) {
        vk::GraphicsPipelineDesc mask;
        mask.vertexShader = "shadow_mask.vert";
        mask.fragmentShader = "shadow_mask.frag";
        mask.colorFormat = kMaskFormat;
        mask.colorWriteMask = VK_COLOR_COMPONENT_R_BIT << k;
        mask.depthStencilFormat = m_depthFormat;
        mask.stencilTest = true;
        mask.stencilFront = stencilOp(VK_STENCIL_OP_ZERO, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_COMPARE_OP_EQUAL);
        mask.stencilBack = mask.stencilFront;
        m_maskPipelines[k] = std::make_unique<vk::GraphicsPipeline>(context, mask);
    }
}

void ShadowVolumePass::record(VkCommandBuffer cmd, const gpu::GpuCamera& camera, float near) const {
    gpu::RasterParams raster{};
    raster.viewProj = rasterViewProjection(camera, near);
    const VkDeviceSize volumeBytesPerLight =
        VkDeviceSize(m_triangleCount) * gpu::kVolumeVerticesPerTriangle * sizeof(glm::vec4);
    const VkPipelineStageFlags2 fragmentTests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    const VkAccessFlags2 depthAccess =
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    const uint64_t pixels = uint64_t(m_width) * m_height;

    vk::imageBarrier(cmd, m_depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, fragmentTests, depthAccess);
    for (uint32_t pass = 0; pass < m_passCount; ++pass) {
        const uint32_t first = pass * gpu::kLightsPerMaskPass;
        const uint32_t count = std::min(gpu::kLightsPerMaskPass, m_lightCount - first);
        const bool computeVolumes = m_geometry == VolumeGeometry::Compute;
        if (pass > 0 && computeVolumes) {
            // The previous pass's draws read the volume buffer this dispatch overwrites.
            vk::memoryBarrier2(cmd, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, VK_ACCESS_2_NONE,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE);
        }
        if (pass > 0) {
            vk::imageBarrier(cmd, m_depth, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                             VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, fragmentTests,
                             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, fragmentTests, depthAccess);
        }
        if (computeVolumes) {
            gpu::ShadowVolumeParams build{m_triangleCount, first, count, 0u};
            m_build.record(cmd, uint64_t(m_triangleCount) * count, build);
            vk::memoryBarrier2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
        }
        vk::imageBarrier(cmd, m_mask, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                         VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);

        VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color.imageView = m_mask.view();
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        color.clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = m_depth.view();
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        depth.loadOp = pass == 0 ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {0.0f, 0};  // reversed depth: 0 is infinitely far
        VkRenderingAttachmentInfo stencil = depth;
        stencil.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, {m_width, m_height}};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &color;
        rendering.pDepthAttachment = &depth;
        rendering.pStencilAttachment = &stencil;
        vkCmdBeginRendering(cmd, &rendering);
        vk::setViewportAndScissor(cmd, m_width, m_height);
        const VkDeviceSize zero = 0;
        if (pass == 0 && m_triangleCount > 0) {
            const VkBuffer positions = m_depthPositions.handle();
            vkCmdBindVertexBuffers(cmd, 0, 1, &positions, &zero);
            const uint32_t twoSided = m_triangleCount - m_culledCount;
            if (twoSided > 0) {
                m_depthPipeline->bind(cmd, raster);
                vkCmdDraw(cmd, twoSided * 3, 1, 0, 0);
            }
            if (m_culledCount > 0) {
                m_depthCullPipeline->bind(cmd, raster);
                vkCmdDraw(cmd, m_culledCount * 3, 1, twoSided * 3, 0);
            }
        }
        for (uint32_t k = 0; k < count; ++k) {
            if (m_triangleCount > 0 && !computeVolumes) {
                gpu::RasterVolumeParams volume{raster.viewProj, m_lightPoints[first + k]};
                m_volumeGeometryPipeline->bind(cmd, volume);
                const VkBuffer positions = m_positions.handle();
                vkCmdBindVertexBuffers(cmd, 0, 1, &positions, &zero);
                vkCmdBindIndexBuffer(cmd, m_adjacency.handle(), 0, VK_INDEX_TYPE_UINT32);
                vkCmdDrawIndexed(cmd, m_triangleCount * 6, 1, 0, 0, 0);
            } else if (m_triangleCount > 0) {
                m_volumePipeline->bind(cmd, raster);
                const VkBuffer volumes = m_volumes.handle();
                const VkDeviceSize offset = k * volumeBytesPerLight;
                vkCmdBindVertexBuffers(cmd, 0, 1, &volumes, &offset);
                vkCmdDraw(cmd, m_triangleCount * gpu::kVolumeVerticesPerTriangle, 1, 0, 0);
            }
            m_maskPipelines[k]->bind(cmd, nullptr, 0);
            vkCmdDraw(cmd, 3, 1, 0, 0);
        }
        vkCmdEndRendering(cmd);

        vk::imageBarrier(cmd, m_mask, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.bufferOffset = VkDeviceSize(pass) * pixels * 4;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {m_width, m_height, 1};
        vkCmdCopyImageToBuffer(cmd, m_mask.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, m_masks.handle(), 1, &region);
    }
    vk::memoryBarrier2(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT);
}

}  // namespace vkp
