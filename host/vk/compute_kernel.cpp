#include "vk/compute_kernel.h"

#include <fmt/format.h>

#include "shared/kernels/scene.glsl"
#include "shared/kernels/terminations.glsl"
#include "util/errors.h"
#include "vk/buffer.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/shader_reflection.h"
#include "vk/shader_registry.h"
#include "vk/texture_array.h"

namespace vkp::vk {

ComputeKernel::ComputeKernel(Context& context, KernelInterface interface)
    : m_context(context), m_interface(std::move(interface)), m_bound(m_interface.bindingCount, false) {
    const VkDevice device = context.device();
    const std::string& name = m_interface.shader;
    const uint32_t bufferCount = m_interface.bindingCount;
    const uint32_t pushBytes = m_interface.pushBytes;
    const auto code = shaderCode(name);
    const ShaderInterface declared = checkKernelInterface(m_interface, code);
    const bool terminations = declared.terminationCounters;
    const bool textures = declared.sceneTextures;
    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = code.size_bytes();
    moduleInfo.pCode = code.data();
    check(vkCreateShaderModule(device, &moduleInfo, nullptr, &m_module),
          fmt::format("creating the shader module {}", name));

    std::vector<VkDescriptorSetLayoutBinding> bindings(bufferCount);
    for (uint32_t i = 0; i < bufferCount; ++i) {
        bindings[i].binding = i;
        bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = bufferCount;
    setInfo.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &m_setLayout), "creating a set layout");
    std::vector<VkDescriptorSetLayout> setLayouts{m_setLayout};
    if (terminations) {  // set gpu::kTerminationSet == 1: the context's termination counters
        static_assert(gpu::kTerminationSet == 1 && gpu::kTerminationBinding == 0);
        VkDescriptorSetLayoutBinding counters{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        VkDescriptorSetLayoutCreateInfo countersInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        countersInfo.bindingCount = 1;
        countersInfo.pBindings = &counters;
        check(vkCreateDescriptorSetLayout(device, &countersInfo, nullptr, &m_terminationLayout),
              "creating a set layout");
        setLayouts.push_back(m_terminationLayout);
    }
    if (textures) {  // set gpu::kSceneTextureSet == 2: the scene's texture array (two views)
        static_assert(gpu::kSceneTextureSet == 2 && gpu::kSceneTextureUnormBinding == 0 &&
                      gpu::kSceneTextureSrgbBinding == 1);
        if (!terminations) {
            VkDescriptorSetLayoutCreateInfo emptyInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
            check(vkCreateDescriptorSetLayout(device, &emptyInfo, nullptr, &m_emptyLayout), "creating a set layout");
            setLayouts.push_back(m_emptyLayout);
        }
        VkDescriptorSetLayoutBinding views[2]{};
        for (uint32_t i = 0; i < 2; ++i)
            views[i] = {i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        VkDescriptorSetLayoutCreateInfo texturesInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        texturesInfo.bindingCount = 2;
        texturesInfo.pBindings = views;
        check(vkCreateDescriptorSetLayout(device, &texturesInfo, nullptr, &m_textureLayout), "creating a set layout");
        setLayouts.push_back(m_textureLayout);
    }

    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = static_cast<uint32_t>(setLayouts.size());
    layoutInfo.pSetLayouts = setLayouts.data();
    layoutInfo.pushConstantRangeCount = pushBytes ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &m_pipelineLayout),
          "creating a pipeline layout");

    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = m_module;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.layout = m_pipelineLayout;
    pipelineInfo.flags = VK_PIPELINE_CREATE_DISPATCH_BASE_BIT;  // windows of items (ItemRange)
    check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &m_pipeline),
          fmt::format("creating the compute pipeline {}", name));

    const VkDescriptorPoolSize poolSizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, std::max(1u, bufferCount + 1u)},
                                               {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2u}};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 3;
    poolInfo.poolSizeCount = textures ? 2 : 1;
    poolInfo.pPoolSizes = poolSizes;
    check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &m_pool), "creating a descriptor pool");
    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = m_pool;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &m_setLayout;
    check(vkAllocateDescriptorSets(device, &allocInfo, &m_set), "allocating a descriptor set");
    if (terminations) {
        allocInfo.pSetLayouts = &m_terminationLayout;
        check(vkAllocateDescriptorSets(device, &allocInfo, &m_terminationSet), "allocating a descriptor set");
        VkDescriptorBufferInfo info{context.terminationCounters().handle(), 0, VK_WHOLE_SIZE};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = m_terminationSet;
        write.dstBinding = gpu::kTerminationBinding;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        write.pBufferInfo = &info;
        vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
    }
    if (textures) {
        allocInfo.pSetLayouts = &m_textureLayout;
        check(vkAllocateDescriptorSets(device, &allocInfo, &m_textureSet), "allocating a descriptor set");
    }
}

ComputeKernel::~ComputeKernel() {
    const VkDevice device = m_context.device();
    vkDestroyDescriptorPool(device, m_pool, nullptr);
    vkDestroyPipeline(device, m_pipeline, nullptr);
    vkDestroyPipelineLayout(device, m_pipelineLayout, nullptr);
    vkDestroyDescriptorSetLayout(device, m_setLayout, nullptr);
    if (m_terminationLayout) vkDestroyDescriptorSetLayout(device, m_terminationLayout, nullptr);
    if (m_emptyLayout) vkDestroyDescriptorSetLayout(device, m_emptyLayout, nullptr);
    if (m_textureLayout) vkDestroyDescriptorSetLayout(device, m_textureLayout, nullptr);
    vkDestroyShaderModule(device, m_module, nullptr);
}

void ComputeKernel::bind(uint32_t binding, const Buffer& buffer) {
    if (binding >= m_interface.bindingCount)
        throw RuntimeError(fmt::format("{}: binding {} out of range", m_interface.shader, binding));
    VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = m_set;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(m_context.device(), 1, &write, 0, nullptr);
    m_bound[binding] = true;
}

void ComputeKernel::bind(const std::vector<const Buffer*>& buffers, uint32_t first) {
    for (uint32_t i = 0; i < buffers.size(); ++i) bind(first + i, *buffers[i]);
}

void ComputeKernel::bind(const KernelBindings& bindings, uint32_t first) {
    bind(bindings.buffers, first);
    if (bindings.textures) bind(*bindings.textures);
}

void ComputeKernel::bind(const TextureArray& textures) {
    if (!m_textureSet) return;
    const VkDescriptorImageInfo infos[2] = {
        {textures.sampler(), textures.unormView(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {textures.sampler(), textures.srgbView(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
    VkWriteDescriptorSet writes[2]{};
    for (uint32_t i = 0; i < 2; ++i) {
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = m_textureSet;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[i].pImageInfo = &infos[i];
    }
    vkUpdateDescriptorSets(m_context.device(), 2, writes, 0, nullptr);
    m_texturesBound = true;
}

void ComputeKernel::record(VkCommandBuffer cmd, uint32_t groups, const void* push, uint32_t pushBytes,
                           uint32_t firstGroup) const {
    for (uint32_t i = 0; i < m_interface.bindingCount; ++i)
        if (!m_bound[i]) throw RuntimeError(fmt::format("{}: binding {} was never bound", m_interface.shader, i));
    if (m_textureSet && !m_texturesBound)
        throw RuntimeError(fmt::format("{}: the scene textures (set {}) were never bound", m_interface.shader,
                                       gpu::kSceneTextureSet));
    if (pushBytes != m_interface.pushBytes)
        throw RuntimeError(fmt::format("{}: push constants are {} bytes, expected {}", m_interface.shader,
                                       pushBytes, m_interface.pushBytes));
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipelineLayout, 0, 1, &m_set, 0, nullptr);
    if (m_terminationSet)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipelineLayout, gpu::kTerminationSet, 1,
                                &m_terminationSet, 0, nullptr);
    if (m_textureSet)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipelineLayout, gpu::kSceneTextureSet, 1,
                                &m_textureSet, 0, nullptr);
    if (pushBytes) vkCmdPushConstants(cmd, m_pipelineLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes, push);
    if (groups && firstGroup) vkCmdDispatchBase(cmd, firstGroup, 0, 0, groups, 1, 1);
    else if (groups) vkCmdDispatch(cmd, groups, 1, 1);
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

}  // namespace vkp::vk
