// Texel-buffer views of storage buffers: the BVH's nodes and triangles read as uniform texel
// buffers (set gpu::kSceneGeometrySet, shaders/render/scene_geometry.glsl; docs/bvh.md).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/buffer.h"
#include "vk/compute_kernel.h"

namespace vkp::vk {

class Context;

// A storage buffer holding `data` (at least 16 bytes) that can also be viewed as a uniform texel buffer.
template <typename T> Buffer makeTexelReadBuffer(Context& context, std::string name, const std::vector<T>& data) {
    const VkDeviceSize bytes = std::max<VkDeviceSize>(16, data.size() * sizeof(T));
    Buffer buffer(context, std::move(name), bytes, kStorageUsage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    if (!data.empty()) buffer.upload(data);
    return buffer;
}

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

// R32G32B32A32_UINT views of a BVH's node buffer (GpuBvhNode: two texels each) and triangle
// buffer (GpuTriangle: three), made with makeTexelReadBuffer. Each view is as long as the device
// allows (maxTexelBufferElements; at least one texel, so the descriptors stay valid); covers():
// whether they reach every node and triangle, i.e. whether the traversal may read through them
// (vk::SceneSpecialization::bvhTexels).
class BvhTexelViews {
public:
    BvhTexelViews() = default;
    BvhTexelViews(const Context& context, const Buffer& nodes, uint64_t nodeCount, const Buffer& triangles,
                  uint64_t triangleCount);

    const SceneGeometryViews& views() const { return m_views; }
    bool covers() const { return m_covers; }

private:
    BufferView m_nodes;
    BufferView m_triangles;
    SceneGeometryViews m_views;
    bool m_covers = false;
};

}  // namespace vkp::vk
