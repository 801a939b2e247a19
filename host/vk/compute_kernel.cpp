#include "vk/compute_kernel.h"

#include <fmt/format.h>

#include "shared/kernels/scene.glsl"
#include "shared/kernels/terminations.glsl"
#include "util/errors.h"
#include "vk/buffer.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/segmented_buffer.h"
#include "vk/texture_array.h"

namespace vkp::vk {

namespace {

// One descriptor of `type` at (set, binding), its resource still to be pointed at.
VkWriteDescriptorSet descriptorWrite(VkDescriptorSet set, uint32_t binding, VkDescriptorType type) {
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = type;
    return write;
}

}  // namespace

ComputeKernel::ComputeKernel(Context& context, KernelInterface interface)
    : m_context(context), m_interface(std::move(interface)), m_bound(m_interface.bindingCount, VK_NULL_HANDLE),
      m_pipeline(&context.computePipeline(m_interface)),
      m_singleSegmentPipeline(&context.computePipeline(m_interface, {}, true)) {
    const VkDevice device = context.device();
    const uint32_t bufferCount = m_interface.bindingCount;
    const VkDescriptorSetLayout setLayout = m_pipeline->bufferSetLayout();
    const VkDescriptorSetLayout terminationLayout = m_pipeline->terminationSetLayout();
    const VkDescriptorSetLayout textureLayout = m_pipeline->textureSetLayout();
    const VkDescriptorSetLayout geometryLayout = m_pipeline->geometrySetLayout();
    VkDescriptorPoolSize poolSizes[3] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, std::max(1u, bufferCount + 1u)}};
    uint32_t poolSizeCount = 1;
    if (textureLayout) poolSizes[poolSizeCount++] = {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2u};
    if (geometryLayout) poolSizes[poolSizeCount++] = {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 2u};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 4;
    poolInfo.poolSizeCount = poolSizeCount;
    poolInfo.pPoolSizes = poolSizes;
    check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &m_pool), "creating a descriptor pool");
    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = m_pool;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &setLayout;
    check(vkAllocateDescriptorSets(device, &allocInfo, &m_set), "allocating a descriptor set");
    if (terminationLayout) {
        allocInfo.pSetLayouts = &terminationLayout;
        check(vkAllocateDescriptorSets(device, &allocInfo, &m_terminationSet), "allocating a descriptor set");
        VkDescriptorBufferInfo info{context.terminationCounters().handle(), 0, VK_WHOLE_SIZE};
        VkWriteDescriptorSet write =
            descriptorWrite(m_terminationSet, gpu::kTerminationBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
        write.pBufferInfo = &info;
        vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
    }
    if (textureLayout) {
        allocInfo.pSetLayouts = &textureLayout;
        check(vkAllocateDescriptorSets(device, &allocInfo, &m_textureSet), "allocating a descriptor set");
    }
    if (geometryLayout) {
        allocInfo.pSetLayouts = &geometryLayout;
        check(vkAllocateDescriptorSets(device, &allocInfo, &m_geometrySet), "allocating a descriptor set");
    }
}

ComputeKernel::~ComputeKernel() { vkDestroyDescriptorPool(m_context.device(), m_pool, nullptr); }

void ComputeKernel::bind(uint32_t binding, const Buffer& buffer) {
    if (binding >= m_interface.bindingCount)
        throw RuntimeError(fmt::format("{}: binding {} out of range", m_interface.shader, binding));
    VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write = descriptorWrite(m_set, binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(m_context.device(), 1, &write, 0, nullptr);
    m_bound[binding] = buffer.handle();
}

void ComputeKernel::bind(const std::vector<const Buffer*>& buffers, uint32_t first) {
    for (uint32_t i = 0; i < buffers.size(); ++i) bind(first + i, *buffers[i]);
}

void ComputeKernel::bind(const KernelBindings& bindings, uint32_t first) {
    bind(bindings.buffers, first);
    if (bindings.textures) bind(*bindings.textures);
    if (bindings.geometry) bind(*bindings.geometry);
    if (bindings.scene) {
        m_pipeline = &m_context.computePipeline(m_interface, *bindings.scene);
        m_singleSegmentPipeline = &m_context.computePipeline(m_interface, *bindings.scene, true);
    }
}

const ComputePipeline& ComputeKernel::dispatchPipeline() const {
    if (m_singleSegmentPipeline == m_pipeline) return *m_pipeline;  // the shader binds no segmented array
    bool segmented = false;
    for (VkBuffer buffer : m_bound)
        if (const auto segments = SegmentedBuffer::segmentsAddressedBy(buffer)) {
            if (*segments > 1) return *m_pipeline;
            segmented = true;
        }
    return segmented ? *m_singleSegmentPipeline : *m_pipeline;
}

void ComputeKernel::bind(const TextureArray& textures) {
    if (!m_textureSet) return;
    const VkDescriptorImageInfo infos[2] = {
        {textures.sampler(), textures.unormView(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {textures.sampler(), textures.srgbView(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
    VkWriteDescriptorSet writes[2]{};
    for (uint32_t i = 0; i < 2; ++i) {
        writes[i] = descriptorWrite(m_textureSet, i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
        writes[i].pImageInfo = &infos[i];
    }
    vkUpdateDescriptorSets(m_context.device(), 2, writes, 0, nullptr);
    m_texturesBound = true;
}

void ComputeKernel::bind(const SceneGeometryViews& views) {
    if (!m_geometrySet) return;
    const VkBufferView handles[2] = {views.nodes, views.triangles};
    static_assert(gpu::kSceneNodeTexelsBinding == 0 && gpu::kSceneTriangleTexelsBinding == 1);
    VkWriteDescriptorSet writes[2]{};
    for (uint32_t i = 0; i < 2; ++i) {
        writes[i] = descriptorWrite(m_geometrySet, i, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
        writes[i].pTexelBufferView = &handles[i];
    }
    vkUpdateDescriptorSets(m_context.device(), 2, writes, 0, nullptr);
    m_geometryBound = true;
}

void ComputeKernel::record(VkCommandBuffer cmd, uint64_t groups, const void* push, uint32_t pushBytes,
                           uint32_t firstGroup, bool rows) const {
    const uint32_t maxGroups = m_context.properties().limits.maxComputeWorkGroupCount[0];
    const bool wide = groups + firstGroup > maxGroups;
    if (wide && (!rows || firstGroup != 0))
        throw std::logic_error(fmt::format("{}: {} workgroups exceed the device's {} per dispatch", m_interface.shader,
                                           groups, maxGroups));
    const uint64_t rowCount = (groups + kRowGroups - 1) / kRowGroups;
    if (wide && rowCount > m_context.properties().limits.maxComputeWorkGroupCount[1])
        throw RuntimeError(fmt::format("{}: {} workgroups exceed the device's dispatch limits", m_interface.shader, groups));
    for (uint32_t i = 0; i < m_interface.bindingCount; ++i)
        if (m_bound[i] == VK_NULL_HANDLE) throw RuntimeError(fmt::format("{}: binding {} was never bound", m_interface.shader, i));
    if (m_textureSet && !m_texturesBound)
        throw RuntimeError(fmt::format("{}: the scene textures (set {}) were never bound", m_interface.shader,
                                       gpu::kSceneTextureSet));
    if (m_geometrySet && !m_geometryBound)
        throw RuntimeError(fmt::format("{}: the BVH texel buffers (set {}) were never bound", m_interface.shader,
                                       gpu::kSceneGeometrySet));
    if (pushBytes != m_interface.pushBytes)
        throw RuntimeError(fmt::format("{}: push constants are {} bytes, expected {}", m_interface.shader,
                                       pushBytes, m_interface.pushBytes));
    const ComputePipeline& pipeline = dispatchPipeline();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, 1, &m_set, 0, nullptr);
    if (m_terminationSet)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), gpu::kTerminationSet, 1,
                                &m_terminationSet, 0, nullptr);
    if (m_textureSet)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), gpu::kSceneTextureSet, 1,
                                &m_textureSet, 0, nullptr);
    if (m_geometrySet)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), gpu::kSceneGeometrySet, 1,
                                &m_geometrySet, 0, nullptr);
    if (pushBytes) vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes, push);
    if (wide) vkCmdDispatch(cmd, kRowGroups, static_cast<uint32_t>(rowCount), 1);
    else if (groups && firstGroup) vkCmdDispatchBase(cmd, firstGroup, 0, 0, static_cast<uint32_t>(groups), 1, 1);
    else if (groups) vkCmdDispatch(cmd, static_cast<uint32_t>(groups), 1, 1);
}

namespace {
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dst, VkAccessFlags dstAccess) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}
}  // namespace

void computeBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT);
}

void computeToHostBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

void transferToComputeBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void transferBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
}

}  // namespace vkp::vk
