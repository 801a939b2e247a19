#include "view/swapchain_presenter.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "util/errors.h"
#include "vk/check.h"
#include "vk/context.h"

namespace vkp {
namespace {

bool isBgra(VkFormat format) { return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB; }

}  // namespace

SwapchainPresenter::SwapchainPresenter(vk::Context& context, VkSurfaceKHR surface, uint32_t width, uint32_t height)
    : m_context(context), m_surface(surface), m_width(width), m_height(height) {
    try {
        if (surface) {
            VkBool32 supported = VK_FALSE;
            vk::check(vkGetPhysicalDeviceSurfaceSupportKHR(context.physicalDevice(), context.queueFamily(), surface,
                                                           &supported),
                      "asking whether the queue presents to the window");
            if (!supported) throw RuntimeError("the device's queue cannot present to the window");
        }
        VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        poolInfo.queueFamilyIndex = context.queueFamily();
        vk::check(vkCreateCommandPool(context.device(), &poolInfo, nullptr, &m_pool), "creating the presenter's command pool");
        VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        allocInfo.commandPool = m_pool;
        allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocInfo.commandBufferCount = 1;
        vk::check(vkAllocateCommandBuffers(context.device(), &allocInfo, &m_cmd), "allocating the presenter's commands");
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        vk::check(vkCreateFence(context.device(), &fenceInfo, nullptr, &m_fence), "creating the presenter's fence");
        VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        vk::check(vkCreateSemaphore(context.device(), &semaphoreInfo, nullptr, &m_acquired), "creating a semaphore");
        createSwapchain();
    } catch (...) {
        release();
        throw;
    }
}

SwapchainPresenter::~SwapchainPresenter() { release(); }

void SwapchainPresenter::release() {
    VkDevice device = m_context.device();
    if (device) vkDeviceWaitIdle(device);
    destroySwapchain();
    if (m_acquired) vkDestroySemaphore(device, m_acquired, nullptr);
    if (m_fence) vkDestroyFence(device, m_fence, nullptr);
    if (m_pool) vkDestroyCommandPool(device, m_pool, nullptr);
    m_acquired = VK_NULL_HANDLE;
    m_fence = VK_NULL_HANDLE;
    m_pool = VK_NULL_HANDLE;
    if (m_surface) vkDestroySurfaceKHR(m_context.instance(), m_surface, nullptr);
    m_surface = VK_NULL_HANDLE;
}

void SwapchainPresenter::createSwapchain() {
    if (offscreen()) {
        m_format = VK_FORMAT_R8G8B8A8_UNORM;
        m_extent = {m_width, m_height};
        m_offscreen = std::make_unique<vk::Image>(m_context, "offscreen window", m_width, m_height, m_format,
                                                  VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,  // vk::Image makes a view
                                                  VK_IMAGE_ASPECT_COLOR_BIT);
        m_images = {m_offscreen->handle()};
        return;
    }
    VkPhysicalDevice gpu = m_context.physicalDevice();
    VkSurfaceCapabilitiesKHR caps{};
    vk::check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, m_surface, &caps), "reading the window's surface");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw RuntimeError("the window's swapchain images cannot be copied to (no TRANSFER_DST usage)");
    uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, m_surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, m_surface, &count, formats.data());
    const auto chosen = std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
        return f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM ||
               f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB;
    });
    if (chosen == formats.end()) throw RuntimeError("the window offers no 8-bit RGBA or BGRA surface format");
    m_format = chosen->format;
    m_extent = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : VkExtent2D{m_width, m_height};
    m_extent.width = std::clamp(m_extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    m_extent.height = std::clamp(m_extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = m_surface;
    info.minImageCount = caps.maxImageCount > 0 ? std::min(caps.minImageCount + 1, caps.maxImageCount) : caps.minImageCount + 1;
    info.imageFormat = chosen->format;
    info.imageColorSpace = chosen->colorSpace;
    info.imageExtent = m_extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // required of every implementation
    info.clipped = VK_TRUE;
    vk::check(vkCreateSwapchainKHR(m_context.device(), &info, nullptr, &m_swapchain), "creating the swapchain");
    vkGetSwapchainImagesKHR(m_context.device(), m_swapchain, &count, nullptr);
    m_images.resize(count);
    vkGetSwapchainImagesKHR(m_context.device(), m_swapchain, &count, m_images.data());
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    m_presentReady.assign(count, VK_NULL_HANDLE);
    for (VkSemaphore& s : m_presentReady)
        vk::check(vkCreateSemaphore(m_context.device(), &semaphoreInfo, nullptr, &s), "creating a semaphore");
}

void SwapchainPresenter::destroySwapchain() {
    VkDevice device = m_context.device();
    for (VkSemaphore s : m_presentReady)
        if (s) vkDestroySemaphore(device, s, nullptr);
    m_presentReady.clear();
    m_images.clear();
    m_offscreen.reset();
    if (m_swapchain) vkDestroySwapchainKHR(device, m_swapchain, nullptr);
    m_swapchain = VK_NULL_HANDLE;
}

bool SwapchainPresenter::bgra() const { return isBgra(m_format); }

void SwapchainPresenter::resize(uint32_t width, uint32_t height) {
    if (width == m_width && height == m_height) return;
    vkDeviceWaitIdle(m_context.device());
    destroySwapchain();
    m_width = width;
    m_height = height;
    createSwapchain();
}

void SwapchainPresenter::present(const vk::Buffer& pixels, const std::function<void(VkCommandBuffer)>& writePixels) {
    VkDevice device = m_context.device();

    uint32_t index = 0;
    VkResult acquired = offscreen() ? VK_SUCCESS
                                    : vkAcquireNextImageKHR(device, m_swapchain, UINT64_MAX, m_acquired, VK_NULL_HANDLE, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {  // the window changed under us: a new swapchain, next time
        vkDeviceWaitIdle(device);
        destroySwapchain();
        createSwapchain();
        return;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) vk::check(acquired, "acquiring a swapchain image");

    vk::check(vkResetCommandBuffer(m_cmd, 0), "resetting the presenter's commands");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk::check(vkBeginCommandBuffer(m_cmd, &begin), "beginning the presenter's commands");
    writePixels(m_cmd);
    VkImageMemoryBarrier toCopy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toCopy.srcAccessMask = 0;
    toCopy.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toCopy.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    toCopy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toCopy.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toCopy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toCopy.image = m_images[index];
    toCopy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(m_cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &toCopy);
    VkBufferImageCopy region{};
    region.bufferRowLength = m_width;
    region.bufferImageHeight = m_height;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {std::min(m_width, m_extent.width), std::min(m_height, m_extent.height), 1};
    vkCmdCopyBufferToImage(m_cmd, pixels.handle(), m_images[index], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    VkImageMemoryBarrier toPresent = toCopy;
    toPresent.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toPresent.dstAccessMask = 0;
    toPresent.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toPresent.newLayout = offscreen() ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    vkCmdPipelineBarrier(m_cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &toPresent);
    vk::check(vkEndCommandBuffer(m_cmd), "ending the presenter's commands");

    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &m_cmd;
    if (!offscreen()) {
        submit.waitSemaphoreCount = 1;
        submit.pWaitSemaphores = &m_acquired;
        submit.pWaitDstStageMask = &waitStage;
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &m_presentReady[index];
    }
    vk::check(vkResetFences(device, 1, &m_fence), "resetting the presenter's fence");
    vk::check(vkQueueSubmit(m_context.queue(), 1, &submit, m_fence), "submitting the window's copy");
    if (offscreen()) {  // the copy is the present
        vk::check(vkWaitForFences(device, 1, &m_fence, VK_TRUE, uint64_t(60e9)), "waiting for the window's copy");
        ++m_presented;
        if (m_context.validationEnabled()) m_context.throwOnValidationMessages();
        return;
    }

    VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    presentInfo.waitSemaphoreCount = 1;
    presentInfo.pWaitSemaphores = &m_presentReady[index];
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &m_swapchain;
    presentInfo.pImageIndices = &index;
    const VkResult presented = vkQueuePresentKHR(m_context.queue(), &presentInfo);
    // The copy must be done before the pixels are written again (and before the next acquire
    // reuses m_acquired).
    vk::check(vkWaitForFences(device, 1, &m_fence, VK_TRUE, uint64_t(60e9)), "waiting for the window's copy");
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
        vkDeviceWaitIdle(device);
        destroySwapchain();
        createSwapchain();
    } else {
        vk::check(presented, "presenting to the window");
    }
    ++m_presented;
    if (m_context.validationEnabled()) m_context.throwOnValidationMessages();
}

}  // namespace vkp
