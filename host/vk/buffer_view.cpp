#include "vk/buffer_view.h"

#include <algorithm>
#include <utility>

#include "vk/buffer.h"
#include "vk/check.h"
#include "vk/context.h"

namespace vkp::vk {

uint64_t uniformTexelCapacity(const Context& context, const Buffer& buffer, VkFormat format, uint32_t texelBytes) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &props);
    if (!(props.bufferFeatures & VK_FORMAT_FEATURE_UNIFORM_TEXEL_BUFFER_BIT)) return 0;
    return std::min<uint64_t>(buffer.size() / texelBytes, context.properties().limits.maxTexelBufferElements);
}

BufferView::BufferView(const Context& context, const Buffer& buffer, VkFormat format, uint32_t texelBytes,
                       uint64_t texels)
    : m_device(context.device()) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.handle();
    info.format = format;
    info.offset = 0;
    info.range = texels * texelBytes;
    check(vkCreateBufferView(m_device, &info, nullptr, &m_view), "creating a buffer view of " + buffer.name());
}

BufferView::~BufferView() {
    if (m_view) vkDestroyBufferView(m_device, m_view, nullptr);
}

BufferView::BufferView(BufferView&& other) noexcept
    : m_device(other.m_device), m_view(std::exchange(other.m_view, VK_NULL_HANDLE)) {}

BufferView& BufferView::operator=(BufferView&& other) noexcept {
    if (this != &other) {
        if (m_view) vkDestroyBufferView(m_device, m_view, nullptr);
        m_device = other.m_device;
        m_view = std::exchange(other.m_view, VK_NULL_HANDLE);
    }
    return *this;
}

}  // namespace vkp::vk
