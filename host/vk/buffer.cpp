#include "vk/buffer.h"

#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "util/errors.h"
#include "vk/check.h"
#include "vk/context.h"

namespace vkp::vk {

Buffer::Buffer(Context& context, std::string name, VkDeviceSize size, VkBufferUsageFlags usage,
               MemoryUse use)
    : m_context(&context), m_name(std::move(name)), m_size(size) {
    const VkDeviceSize limit = context.properties().limits.maxStorageBufferRange;
    if ((usage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) && size > limit)
        throw InputError(fmt::format(
            "the {} buffer needs {:.1f} MiB but the device '{}' addresses at most {:.1f} MiB per "
            "storage buffer; reduce the scene, image or photon count",
            m_name, size / 1048576.0, context.deviceName(), limit / 1048576.0));
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    const VkDevice device = context.device();
    check(vkCreateBuffer(device, &info, nullptr, &m_buffer), fmt::format("creating the {} buffer", m_name));

    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(device, m_buffer, &req);
    VkMemoryPropertyFlags required = 0, preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (use == MemoryUse::Readback) {
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        preferred = required | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
    }
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = context.findMemoryType(req.memoryTypeBits, required, preferred);
    VkMemoryAllocateFlagsInfo allocFlags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    allocFlags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    if (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) alloc.pNext = &allocFlags;
    try {
        check(vkAllocateMemory(device, &alloc, nullptr, &m_memory),
              fmt::format("allocating {:.1f} MiB for the {} buffer", size / 1048576.0, m_name));
        m_allocated = req.size;
        context.memory().allocated(m_allocated);
        check(vkBindBufferMemory(device, m_buffer, m_memory, 0), "binding buffer memory");
        VkPhysicalDeviceMemoryProperties memProps{};
        vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &memProps);
        const VkMemoryPropertyFlags flags = memProps.memoryTypes[alloc.memoryTypeIndex].propertyFlags;
        const VkMemoryPropertyFlags mappable =
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        if ((flags & mappable) == mappable)
            check(vkMapMemory(device, m_memory, 0, VK_WHOLE_SIZE, 0, &m_mapped), "mapping memory");
    } catch (...) {
        release();
        throw;
    }
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        m_context = std::exchange(other.m_context, nullptr);
        m_name = std::move(other.m_name);
        m_buffer = std::exchange(other.m_buffer, VK_NULL_HANDLE);
        m_memory = std::exchange(other.m_memory, VK_NULL_HANDLE);
        m_size = std::exchange(other.m_size, 0);
        m_allocated = std::exchange(other.m_allocated, 0);
        m_mapped = std::exchange(other.m_mapped, nullptr);
    }
    return *this;
}

void Buffer::release() {
    if (!m_context) return;
    const VkDevice device = m_context->device();
    if (m_mapped) vkUnmapMemory(device, m_memory);
    if (m_buffer) vkDestroyBuffer(device, m_buffer, nullptr);
    if (m_memory) vkFreeMemory(device, m_memory, nullptr);
    m_context->memory().freed(std::exchange(m_allocated, 0));
    m_buffer = VK_NULL_HANDLE;
    m_memory = VK_NULL_HANDLE;
    m_mapped = nullptr;
    m_context = nullptr;
}

void Buffer::upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
    if (bytes == 0) return;
    if (offset + bytes > m_size)
        throw RuntimeError(fmt::format("upload of {} bytes overflows the {} buffer", bytes, m_name));
    if (m_mapped) {
        std::memcpy(static_cast<char*>(m_mapped) + offset, data, bytes);
        return;
    }
    Buffer staging(*m_context, m_name + " staging", bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                   MemoryUse::Readback);
    staging.upload(data, bytes);
    m_context->submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, offset, bytes};
        vkCmdCopyBuffer(cmd, staging.handle(), m_buffer, 1, &region);
    });
}

void Buffer::download(void* data, VkDeviceSize bytes, VkDeviceSize offset) const {
    if (bytes == 0) return;
    if (offset + bytes > m_size)
        throw RuntimeError(fmt::format("download of {} bytes overflows the {} buffer", bytes, m_name));
    if (m_mapped) {
        std::memcpy(data, static_cast<const char*>(m_mapped) + offset, bytes);
        return;
    }
    Buffer staging(*m_context, m_name + " readback", bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                   MemoryUse::Readback);
    m_context->submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{offset, 0, bytes};
        vkCmdCopyBuffer(cmd, m_buffer, staging.handle(), 1, &region);
    });
    staging.download(data, bytes);
}

VkDeviceAddress Buffer::deviceAddress() const {
    VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    info.buffer = m_buffer;
    return vkGetBufferDeviceAddress(m_context->device(), &info);
}

void Buffer::fillZero(VkCommandBuffer cmd) const { vkCmdFillBuffer(cmd, m_buffer, 0, VK_WHOLE_SIZE, 0); }

}  // namespace vkp::vk
