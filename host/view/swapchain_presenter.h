// Shows 8-bit sRGB images in the viewer's window through a Vulkan swapchain: the caller records
// the work that writes the image's bytes into a device buffer (view/display_pass.h), and the same
// submission copies them into the acquired swapchain image (transfer only: no graphics pipeline)
// before it is presented (FIFO). The copy keeps the bytes, so the sRGB encoding the PNG uses is
// what the screen gets, whether the surface format is UNORM or SRGB; bgra() says which byte order
// the surface wants.
//
// Without a surface (`view --headless`) the same submission copies into an image of the window's
// size that stands in for the swapchain's: every step but the window system's present, on any
// device (VK_EXT_headless_surface would be the alternative, but the NVIDIA driver lacks it).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/buffer.h"
#include "vk/image.h"

namespace vkp {
namespace vk { class Context; }

class SwapchainPresenter {
public:
    // Takes ownership of `surface` (created on context's instance; VK_NULL_HANDLE: offscreen).
    // Throws RuntimeError when the surface offers no 8-bit RGBA/BGRA format or no
    // transfer-destination swapchain images.
    SwapchainPresenter(vk::Context& context, VkSurfaceKHR surface, uint32_t width, uint32_t height);
    ~SwapchainPresenter();
    SwapchainPresenter(const SwapchainPresenter&) = delete;
    SwapchainPresenter& operator=(const SwapchainPresenter&) = delete;

    // Records `writePixels` (which leaves `pixels` visible to transfers: width x height words of
    // R, G, B, A bytes, or B, G, R, A where bgra(), top row first), copies `pixels` into the
    // acquired image and presents it; waits until the submission is done.
    void present(const vk::Buffer& pixels, const std::function<void(VkCommandBuffer)>& writePixels);
    bool bgra() const;
    // The images are width x height from now on (the window was resized; the swapchain is made
    // again).
    void resize(uint32_t width, uint32_t height);
    bool offscreen() const { return m_surface == VK_NULL_HANDLE; }
    uint64_t presented() const { return m_presented; }

private:
    void createSwapchain();
    void destroySwapchain();
    void release();

    vk::Context& m_context;
    VkSurfaceKHR m_surface;
    uint32_t m_width, m_height;
    VkSwapchainKHR m_swapchain = VK_NULL_HANDLE;
    VkFormat m_format = VK_FORMAT_UNDEFINED;
    VkExtent2D m_extent{};
    std::vector<VkImage> m_images;
    std::unique_ptr<vk::Image> m_offscreen;  // offscreen(): the image that stands in for the swapchain's
    std::vector<VkSemaphore> m_presentReady;  // per swapchain image: its copy finished
    VkSemaphore m_acquired = VK_NULL_HANDLE;
    VkCommandPool m_pool = VK_NULL_HANDLE;
    VkCommandBuffer m_cmd = VK_NULL_HANDLE;
    VkFence m_fence = VK_NULL_HANDLE;
    uint64_t m_presented = 0;
};

}  // namespace vkp
