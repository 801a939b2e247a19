#include "vk/texture_array.h"

#include <algorithm>

#include <fmt/format.h>

#include "util/errors.h"
#include "vk/buffer.h"
#include "vk/check.h"
#include "vk/context.h"

namespace vkp::vk {
namespace {

constexpr VkFormat kUnorm = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkImageUsageFlags kUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
constexpr uint64_t kStagingBytes = uint64_t(64) << 20;

void layoutBarrier(VkCommandBuffer cmd, VkImage image, uint32_t firstLayer, uint32_t layers, VkImageLayout from,
                   VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, firstLayer, layers};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace

TextureArrayLimits textureArrayLimits(const Context& context) {
    VkImageFormatProperties props{};
    check(vkGetPhysicalDeviceImageFormatProperties(context.physicalDevice(), kUnorm, VK_IMAGE_TYPE_2D,
                                                   VK_IMAGE_TILING_OPTIMAL, kUsage,
                                                   VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT, &props),
          "querying the RGBA8 image limits");
    VkPhysicalDeviceMaintenance3Properties m3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    p2.pNext = &m3;
    vkGetPhysicalDeviceProperties2(context.physicalDevice(), &p2);
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &memory);
    uint64_t largestHeap = 0;
    for (uint32_t i = 0; i < memory.memoryHeapCount; ++i)
        if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            largestHeap = std::max<uint64_t>(largestHeap, memory.memoryHeaps[i].size);
    TextureArrayLimits limits;
    limits.maxSize = std::min(props.maxExtent.width, props.maxExtent.height);
    limits.maxLayers = props.maxArrayLayers;
    // Half the device-local heap: the rest of the scene, the film and the photon maps need room too.
    limits.maxBytes = std::min<uint64_t>({props.maxResourceSize, m3.maxMemoryAllocationSize, largestHeap / 2});
    return limits;
}

TextureArray::TextureArray(Context& context, std::string name, uint32_t width, uint32_t height, uint32_t layers,
                           std::span<const uint32_t> texels)
    : m_context(context), m_name(std::move(name)) {
    const VkDevice device = context.device();
    const uint64_t layerTexels = uint64_t(width) * height;
    if (texels.size() != layerTexels * layers)
        throw RuntimeError(fmt::format("the {} image: {} texels for {}x{}x{}", m_name, texels.size(), width, height, layers));
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = kUnorm;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = kUsage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device, &info, nullptr, &m_image), fmt::format("creating the {} image", m_name));
    try {
        VkMemoryRequirements req{};
        vkGetImageMemoryRequirements(device, m_image, &req);
        m_bytes = req.size;
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = context.findMemoryType(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        check(vkAllocateMemory(device, &alloc, nullptr, &m_memory),
              fmt::format("allocating {:.1f} MiB for the {} image", req.size / 1048576.0, m_name));
        context.memory().allocated(m_bytes);
        check(vkBindImageMemory(device, m_image, m_memory, 0), "binding image memory");
        for (VkFormat format : {kUnorm, VK_FORMAT_R8G8B8A8_SRGB}) {
            VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
            viewInfo.image = m_image;
            viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
            viewInfo.format = format;
            viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
            check(vkCreateImageView(device, &viewInfo, nullptr, format == kUnorm ? &m_unormView : &m_srgbView),
                  fmt::format("creating the {} image view", m_name));
        }
        VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        samplerInfo.magFilter = VK_FILTER_NEAREST;
        samplerInfo.minFilter = VK_FILTER_NEAREST;
        samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        check(vkCreateSampler(device, &samplerInfo, nullptr, &m_sampler), "creating a sampler");

        // Upload bands of rows through a host-visible staging buffer of at most kStagingBytes.
        const uint32_t bandRows = static_cast<uint32_t>(std::clamp<uint64_t>(kStagingBytes / (uint64_t(width) * 4), 1, height));
        context.submitAndWait([&](VkCommandBuffer cmd) {
            layoutBarrier(cmd, m_image, 0, layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT);
        });
        Buffer staging(context, m_name + " staging", uint64_t(bandRows) * width * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       MemoryUse::Readback);
        for (uint32_t layer = 0; layer < layers; ++layer)
            for (uint32_t row = 0; row < height; row += bandRows) {
                const uint32_t rows = std::min(bandRows, height - row);
                staging.upload(texels.data() + layerTexels * layer + uint64_t(row) * width, uint64_t(rows) * width * 4);
                context.submitAndWait([&](VkCommandBuffer cmd) {
                    VkBufferImageCopy region{};
                    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, layer, 1};
                    region.imageOffset = {0, static_cast<int32_t>(row), 0};
                    region.imageExtent = {width, rows, 1};
                    vkCmdCopyBufferToImage(cmd, staging.handle(), m_image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                                           &region);
                });
            }
        context.submitAndWait([&](VkCommandBuffer cmd) {
            layoutBarrier(cmd, m_image, 0, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          VK_ACCESS_2_SHADER_READ_BIT);
        });
    } catch (...) {
        release();
        throw;
    }
}

TextureArray::~TextureArray() { release(); }

void TextureArray::release() {
    const VkDevice device = m_context.device();
    if (m_sampler) vkDestroySampler(device, m_sampler, nullptr);
    if (m_srgbView) vkDestroyImageView(device, m_srgbView, nullptr);
    if (m_unormView) vkDestroyImageView(device, m_unormView, nullptr);
    if (m_image) vkDestroyImage(device, m_image, nullptr);
    if (m_memory) {
        vkFreeMemory(device, m_memory, nullptr);
        m_context.memory().freed(m_bytes);
    }
    m_sampler = VK_NULL_HANDLE;
    m_srgbView = m_unormView = VK_NULL_HANDLE;
    m_image = VK_NULL_HANDLE;
    m_memory = VK_NULL_HANDLE;
}

}  // namespace vkp::vk
