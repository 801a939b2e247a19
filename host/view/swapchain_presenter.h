// Shows 8-bit sRGB images in the viewer's window through a Vulkan swapchain: each image is
// written into a host-visible staging buffer and copied into the acquired swapchain image
// (transfer only: no graphics pipeline), then presented (FIFO). The copy keeps the bytes, so the
// sRGB encoding the PNG uses is what the screen gets, whether the surface format is UNORM or SRGB.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/buffer.h"

namespace vkp {
namespace vk { class Context; }

class SwapchainPresenter {
public:
    // Takes ownership of `surface` (created on context's instance). Throws RuntimeError when the
    // surface offers no 8-bit RGBA/BGRA format or no transfer-destination swapchain images.
    SwapchainPresenter(vk::Context& context, VkSurfaceKHR surface, uint32_t width, uint32_t height);
    ~SwapchainPresenter();
    SwapchainPresenter(const SwapchainPresenter&) = delete;
    SwapchainPresenter& operator=(const SwapchainPresenter&) = delete;

    // Presents `rgba` (width x height, R G B A bytes, top row first); waits until the copy is done.
    void present(const std::vector<uint8_t>& rgba);
    uint64_t presented() const { return m_presented; }

private:
    void createSwapchain();
    void destroySwapchain();
    void release();  // everything but the staging buffer (which releases itself)

    vk::Context& m_context;
    VkSurfaceKHR m_surface;
    uint32_t m_width, m_height;
    VkSwapchainKHR m_swapchain = VK_NULL_HANDLE;
    VkFormat m_format = VK_FORMAT_UNDEFINED;
    VkExtent2D m_extent{};
    std::vector<VkImage> m_images;
    std::vector<VkSemaphore> m_presentReady;  // per swapchain image: its copy finished
    VkSemaphore m_acquired = VK_NULL_HANDLE;
    VkCommandPool m_pool = VK_NULL_HANDLE;
    VkCommandBuffer m_cmd = VK_NULL_HANDLE;
    VkFence m_fence = VK_NULL_HANDLE;
    vk::Buffer m_staging;
    uint64_t m_presented = 0;
};

}  // namespace vkp
