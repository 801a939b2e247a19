#include "vk/buffer_view.h"

#include <utility>

#include "shared/gpu_types.glsl"
#include "vk/check.h"
#include "vk/context.h"

namespace vkp::vk {

BufferView::BufferView(const Context& context, const Buffer& buffer, VkFormat format, uint32_t texelBytes,
                       uint64_t texels)
    : m_device(context.device()) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.handle();
    info.format = format;
    info.offset = 0;
    info.range = texels * texelBytes;
    check(vkCreateBufferView(m_device, &info, nullptr, &m_view), "creating a texel view of the " + buffer.name() + " buffer");
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

namespace {
constexpr VkFormat kBvhTexelFormat = VK_FORMAT_R32G32B32A32_UINT;  // uniform texel buffers must support it
constexpr uint32_t kBvhTexelBytes = 16;
static_assert(sizeof(gpu::GpuBvhNode) == 2 * kBvhTexelBytes && sizeof(gpu::GpuTriangle) == 3 * kBvhTexelBytes);
}  // namespace

BvhTexelViews::BvhTexelViews(const Context& context, const Buffer& nodes, uint64_t nodeCount, const Buffer& triangles,
                             uint64_t triangleCount) {
    const uint64_t maxTexels = context.properties().limits.maxTexelBufferElements;
    const uint64_t nodeTexels = std::min(nodes.size() / kBvhTexelBytes, maxTexels);
    const uint64_t triangleTexels = std::min(triangles.size() / kBvhTexelBytes, maxTexels);
    m_nodes = BufferView(context, nodes, kBvhTexelFormat, kBvhTexelBytes, std::max<uint64_t>(1, nodeTexels));
    m_triangles = BufferView(context, triangles, kBvhTexelFormat, kBvhTexelBytes, std::max<uint64_t>(1, triangleTexels));
    m_views = {m_nodes.handle(), m_triangles.handle()};
    m_covers = nodeTexels >= 2 * nodeCount && triangleTexels >= 3 * triangleCount;
}

}  // namespace vkp::vk
