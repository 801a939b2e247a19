// A texel-buffer view of (the first part of) a vk::Buffer, for uniform texel buffers
// (shaders/scene_geometry.glsl reads the BVH through them).
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

namespace vkp::vk {

class Buffer;
class Context;

// Texels of `format` (bytes each) a uniform texel-buffer view of `buffer` can cover on this device:
// min(buffer size / texelBytes, maxTexelBufferElements); 0 when the format cannot be a uniform
// texel buffer there.
uint64_t uniformTexelCapacity(const Context& context, const Buffer& buffer, VkFormat format, uint32_t texelBytes);

class BufferView {
public:
    BufferView() = default;
    // A view of `texels` texels of `format` (texelBytes each) from the start of `buffer`, which
    // needs VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT.
    BufferView(const Context& context, const Buffer& buffer, VkFormat format, uint32_t texelBytes, uint64_t texels);
    ~BufferView();
    BufferView(BufferView&& other) noexcept;
    BufferView& operator=(BufferView&& other) noexcept;
    BufferView(const BufferView&) = delete;
    BufferView& operator=(const BufferView&) = delete;

    VkBufferView handle() const { return m_view; }

private:
    VkDevice m_device = VK_NULL_HANDLE;
    VkBufferView m_view = VK_NULL_HANDLE;
};

}  // namespace vkp::vk
