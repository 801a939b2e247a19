// A VkBuffer with its own memory. Storage buffers larger than the device's maxStorageBufferRange
// are refused with a message naming the buffer, since a shader could not address all of them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace vkp::vk {

class Context;

enum class MemoryUse {
    Device,    // GPU-local; filled by upload() through a staging copy
    Readback,  // host-visible, cached: results read by the CPU
};

class Buffer {
public:
    Buffer() = default;
    Buffer(Context& context, std::string name, VkDeviceSize size, VkBufferUsageFlags usage,
           MemoryUse use = MemoryUse::Device);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return m_buffer; }
    VkDeviceSize size() const { return m_size; }
    const std::string& name() const { return m_name; }
    explicit operator bool() const { return m_buffer != VK_NULL_HANDLE; }

    // Copies bytes into the buffer at `offset` (directly when mapped, else through staging).
    void upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
    template <typename T> void upload(std::span<const T> data) { upload(data.data(), data.size_bytes()); }
    template <typename T> void upload(const std::vector<T>& data) { upload(data.data(), data.size() * sizeof(T)); }

    // Copies the whole buffer to the host (through a readback buffer when not mapped).
    void download(void* data, VkDeviceSize bytes, VkDeviceSize offset = 0) const;
    template <typename T> std::vector<T> download() const {
        std::vector<T> out(m_size / sizeof(T));
        download(out.data(), out.size() * sizeof(T));
        return out;
    }

    void fillZero(VkCommandBuffer cmd) const;
    // The buffer's address for shaders (usage kSegmentUsage: vk/segmented_buffer.h).
    VkDeviceAddress deviceAddress() const;

private:
    void release();

    Context* m_context = nullptr;
    std::string m_name;
    VkBuffer m_buffer = VK_NULL_HANDLE;
    VkDeviceMemory m_memory = VK_NULL_HANDLE;
    VkDeviceSize m_size = 0;
    VkDeviceSize m_allocated = 0;  // bytes of m_memory (counted by the context's MemoryTracker)
    void* m_mapped = nullptr;  // set when the memory is host-visible and coherent
};

// Usage for buffers read and written by compute shaders and copied to and from.
constexpr VkBufferUsageFlags kStorageUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// Usage for buffers shaders reach through their device address (GL_EXT_buffer_reference), not
// through a descriptor: not bound by maxStorageBufferRange, only by the allocation limits.
constexpr VkBufferUsageFlags kSegmentUsage = VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// A storage buffer holding `data`; at least 16 bytes so empty arrays still bind.
template <typename T>
Buffer makeStorageBuffer(Context& context, std::string name, const std::vector<T>& data) {
    const VkDeviceSize bytes = std::max<VkDeviceSize>(16, data.size() * sizeof(T));
    Buffer buffer(context, std::move(name), bytes, kStorageUsage);
    if (!data.empty()) buffer.upload(data);
    return buffer;
}

}  // namespace vkp::vk
