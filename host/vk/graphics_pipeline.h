// One graphics pipeline for dynamic rendering (Vulkan 1.3, no render pass objects): vertex and
// optional fragment shader from the shader registry, at most one vertex buffer of vec4 positions,
// push constants, fixed depth/stencil/colour-write state, dynamic viewport and scissor. The raster
// pass builds several (depth pre-pass, shadow volumes, one mask writer per RGBA channel).
#pragma once

#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

namespace vkp::vk {

class Context;

struct GraphicsPipelineDesc {
    std::string vertexShader;                  // e.g. "raster_position.vert"
    std::string geometryShader;                // "" = none (needs Context::geometryShaderEnabled())
    std::string fragmentShader;                // "" = no fragment stage (depth/stencil only)
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    uint32_t vertexStride = 0;                 // 0 = no vertex input; else vec4 at location 0
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    bool depthTest = false;
    bool depthWrite = false;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS;
    bool stencilTest = false;
    VkStencilOpState stencilFront{};           // counter-clockwise in framebuffer space
    VkStencilOpState stencilBack{};
    VkFormat colorFormat = VK_FORMAT_UNDEFINED;  // UNDEFINED = no colour attachment
    VkColorComponentFlags colorWriteMask = 0;
    VkFormat depthStencilFormat = VK_FORMAT_UNDEFINED;
    uint32_t pushConstantBytes = 0;            // visible to every stage of the pipeline
};

class GraphicsPipeline {
public:
    GraphicsPipeline(Context& context, const GraphicsPipelineDesc& desc);
    ~GraphicsPipeline();
    GraphicsPipeline(const GraphicsPipeline&) = delete;
    GraphicsPipeline& operator=(const GraphicsPipeline&) = delete;

    // Binds the pipeline and pushes `pushBytes` (must equal the declared size) of constants.
    void bind(VkCommandBuffer cmd, const void* push, uint32_t pushBytes) const;
    template <typename Push> void bind(VkCommandBuffer cmd, const Push& push) const {
        bind(cmd, &push, sizeof(Push));
    }

private:
    void release();

    Context& m_context;
    std::string m_name;
    uint32_t m_pushBytes;
    VkShaderModule m_vertex = VK_NULL_HANDLE;
    VkShaderModule m_geometry = VK_NULL_HANDLE;
    VkShaderModule m_fragment = VK_NULL_HANDLE;
    VkShaderStageFlags m_pushStages = 0;
    VkPipelineLayout m_layout = VK_NULL_HANDLE;
    VkPipeline m_pipeline = VK_NULL_HANDLE;
};

// Sets a viewport and scissor covering width x height (the pipelines keep them dynamic).
void setViewportAndScissor(VkCommandBuffer cmd, uint32_t width, uint32_t height);

}  // namespace vkp::vk
