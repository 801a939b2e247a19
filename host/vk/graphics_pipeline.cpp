#include "vk/graphics_pipeline.h"

#include <vector>

#include <fmt/format.h>

#include "util/errors.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/shader_registry.h"

namespace vkp::vk {
namespace {

VkShaderModule makeModule(VkDevice device, const std::string& name) {
    const auto code = shaderCode(name);
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = code.size_bytes();
    info.pCode = code.data();
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device, &info, nullptr, &module), fmt::format("creating the shader module {}", name));
    return module;
}

}  // namespace

GraphicsPipeline::GraphicsPipeline(Context& context, const GraphicsPipelineDesc& desc)
    : m_context(context), m_name(desc.vertexShader + "+" + desc.fragmentShader),
      m_pushBytes(desc.pushConstantBytes) {
    const VkDevice device = context.device();
    try {
        std::vector<VkPipelineShaderStageCreateInfo> stages;
        m_vertex = makeModule(device, desc.vertexShader);
        VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
        stage.module = m_vertex;
        stage.pName = "main";
        stages.push_back(stage);
        if (!desc.geometryShader.empty()) {
            if (!context.geometryShaderEnabled())
                throw RuntimeError(fmt::format("{}: the device has no geometry shaders", desc.geometryShader));
            m_geometry = makeModule(device, desc.geometryShader);
            stage.stage = VK_SHADER_STAGE_GEOMETRY_BIT;
            stage.module = m_geometry;
            stages.push_back(stage);
        }
        if (!desc.fragmentShader.empty()) {
            m_fragment = makeModule(device, desc.fragmentShader);
            stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
            stage.module = m_fragment;
            stages.push_back(stage);
        }

        m_pushStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT |
                       (m_geometry ? VkShaderStageFlags(VK_SHADER_STAGE_GEOMETRY_BIT) : VkShaderStageFlags(0));
        VkPushConstantRange range{m_pushStages, 0, m_pushBytes};
        VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layoutInfo.pushConstantRangeCount = m_pushBytes ? 1 : 0;
        layoutInfo.pPushConstantRanges = &range;
        check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &m_layout), "creating a pipeline layout");

        VkVertexInputBindingDescription binding{0, desc.vertexStride, VK_VERTEX_INPUT_RATE_VERTEX};
        VkVertexInputAttributeDescription attribute{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0};
        VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
        if (desc.vertexStride) {
            vertexInput.vertexBindingDescriptionCount = 1;
            vertexInput.pVertexBindingDescriptions = &binding;
            vertexInput.vertexAttributeDescriptionCount = 1;
            vertexInput.pVertexAttributeDescriptions = &attribute;
        }
        VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
        assembly.topology = desc.topology;
        VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
        viewport.viewportCount = 1;
        viewport.scissorCount = 1;
        VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
        raster.depthClampEnable = VK_FALSE;
        raster.polygonMode = VK_POLYGON_MODE_FILL;
        raster.cullMode = desc.cullMode;
        raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
        raster.lineWidth = 1.0f;
        VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
        multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
        VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
        depth.depthTestEnable = desc.depthTest ? VK_TRUE : VK_FALSE;
        depth.depthWriteEnable = desc.depthWrite ? VK_TRUE : VK_FALSE;
        depth.depthCompareOp = desc.depthCompare;
        depth.stencilTestEnable = desc.stencilTest ? VK_TRUE : VK_FALSE;
        depth.front = desc.stencilFront;
        depth.back = desc.stencilBack;
        depth.maxDepthBounds = 1.0f;
        VkPipelineColorBlendAttachmentState blendAttachment{};
        blendAttachment.colorWriteMask = desc.colorWriteMask;
        VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
        const bool hasColor = desc.colorFormat != VK_FORMAT_UNDEFINED;
        blend.attachmentCount = hasColor ? 1 : 0;
        blend.pAttachments = &blendAttachment;
        const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
        VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
        dynamic.dynamicStateCount = 2;
        dynamic.pDynamicStates = dynamicStates;

        VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
        rendering.colorAttachmentCount = hasColor ? 1 : 0;
        rendering.pColorAttachmentFormats = &desc.colorFormat;
        rendering.depthAttachmentFormat = desc.depthStencilFormat;
        rendering.stencilAttachmentFormat = desc.depthStencilFormat;

        VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
        info.pNext = &rendering;
        info.stageCount = static_cast<uint32_t>(stages.size());
        info.pStages = stages.data();
        info.pVertexInputState = &vertexInput;
        info.pInputAssemblyState = &assembly;
        info.pViewportState = &viewport;
        info.pRasterizationState = &raster;
        info.pMultisampleState = &multisample;
        info.pDepthStencilState = &depth;
        info.pColorBlendState = &blend;
        info.pDynamicState = &dynamic;
        info.layout = m_layout;
        check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &m_pipeline),
              fmt::format("creating the graphics pipeline {}", m_name));
    } catch (...) {
        release();
        throw;
    }
}

GraphicsPipeline::~GraphicsPipeline() { release(); }

void GraphicsPipeline::release() {
    const VkDevice device = m_context.device();
    if (m_pipeline) vkDestroyPipeline(device, m_pipeline, nullptr);
    if (m_layout) vkDestroyPipelineLayout(device, m_layout, nullptr);
    if (m_fragment) vkDestroyShaderModule(device, m_fragment, nullptr);
    if (m_geometry) vkDestroyShaderModule(device, m_geometry, nullptr);
    m_geometry = VK_NULL_HANDLE;
    if (m_vertex) vkDestroyShaderModule(device, m_vertex, nullptr);
    m_pipeline = VK_NULL_HANDLE;
    m_layout = VK_NULL_HANDLE;
    m_fragment = VK_NULL_HANDLE;
    m_vertex = VK_NULL_HANDLE;
}

void GraphicsPipeline::bind(VkCommandBuffer cmd, const void* push, uint32_t pushBytes) const {
    if (pushBytes != m_pushBytes)
        throw RuntimeError(fmt::format("{}: push constants are {} bytes, expected {}", m_name, pushBytes, m_pushBytes));
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_pipeline);
    if (pushBytes)
        vkCmdPushConstants(cmd, m_layout, m_pushStages, 0, pushBytes, push);
}

void setViewportAndScissor(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
    VkViewport viewport{0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {width, height}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace vkp::vk
