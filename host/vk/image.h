// A 2-D VkImage with its own memory and one view over all of it: the raster pass's attachments
// (depth-stencil, shadow mask). Layout transitions are the caller's (imageBarrier).
#pragma once

#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

namespace vkp::vk {

class Context;

class Image {
public:
    Image(Context& context, std::string name, uint32_t width, uint32_t height, VkFormat format,
          VkImageUsageFlags usage, VkImageAspectFlags aspect);
    ~Image();
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    VkImage handle() const { return m_image; }
    VkImageView view() const { return m_view; }
    VkFormat format() const { return m_format; }
    VkImageAspectFlags aspect() const { return m_aspect; }
    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }

private:
    void release();

    Context& m_context;
    std::string m_name;
    uint32_t m_width;
    uint32_t m_height;
    VkFormat m_format;
    VkImageAspectFlags m_aspect;
    VkImage m_image = VK_NULL_HANDLE;
    VkDeviceMemory m_memory = VK_NULL_HANDLE;
    VkDeviceSize m_allocated = 0;  // bytes of m_memory (counted by the context's MemoryTracker)
    VkImageView m_view = VK_NULL_HANDLE;
};

// One synchronization2 image barrier over the whole image (layout transition and/or hazard).
void imageBarrier(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

// One synchronization2 global memory barrier (buffer hazards between stages).
void memoryBarrier2(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                    VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

// The first depth-stencil format with an 8-bit stencil the device can render to.
VkFormat pickDepthStencilFormat(const Context& context);

}  // namespace vkp::vk
