// An RGBA8 2-D array image that compute shaders read with texelFetch: the scene's texture atlas
// (gpu_scene/texture_atlas.h). Created MUTABLE_FORMAT with two views, R8G8B8A8_UNORM and
// R8G8B8A8_SRGB, so sRGB textures are decoded by the sampler hardware; bound as the two combined
// image samplers of descriptor set gpu::kSceneTextureSet (vk::ComputeKernel::bind).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include <vulkan/vulkan.h>

namespace vkp::vk {

class Context;

// The device's limits for such an image: largest layer side, layer count and bytes.
struct TextureArrayLimits {
    uint32_t maxSize = 0;
    uint32_t maxLayers = 0;
    uint64_t maxBytes = 0;
};
TextureArrayLimits textureArrayLimits(const Context& context);

class TextureArray {
public:
    // Uploads `texels` (width x height x layers RGBA8, R in the low byte); leaves the image in
    // SHADER_READ_ONLY_OPTIMAL. Throws RuntimeError (a device error) when it cannot be created.
    TextureArray(Context& context, std::string name, uint32_t width, uint32_t height, uint32_t layers,
                 std::span<const uint32_t> texels);
    ~TextureArray();
    TextureArray(const TextureArray&) = delete;
    TextureArray& operator=(const TextureArray&) = delete;

    VkImageView unormView() const { return m_unormView; }
    VkImageView srgbView() const { return m_srgbView; }
    VkSampler sampler() const { return m_sampler; }
    uint64_t bytes() const { return m_bytes; }

private:
    void release();

    Context& m_context;
    std::string m_name;
    uint64_t m_bytes = 0;
    VkImage m_image = VK_NULL_HANDLE;
    VkDeviceMemory m_memory = VK_NULL_HANDLE;
    VkImageView m_unormView = VK_NULL_HANDLE;
    VkImageView m_srgbView = VK_NULL_HANDLE;
    VkSampler m_sampler = VK_NULL_HANDLE;
};

}  // namespace vkp::vk
