#include "render/film.h"

#include "vk/compute_kernel.h"

namespace vkp {

Film::Film(vk::Context& context, uint32_t width, uint32_t height)
    : m_width(width), m_height(height),
      m_sums(context, "film", uint64_t(width) * height * sizeof(glm::vec4), vk::kStorageUsage),
      m_counters(context, "film counters", gpu::kPathTraceCounterCount * sizeof(uint32_t), vk::kStorageUsage) {}

void Film::recordClear(VkCommandBuffer cmd) const {
    m_sums.fillZero(cmd);
    m_counters.fillZero(cmd);
    vk::transferToComputeBarrier(cmd);
}

ImageRgb Film::resolve() const {
    return resolveFilm(m_sums.download<glm::vec4>(), m_width, m_height);
}

PathTraceCounters Film::readCounters() const { return PathTracePass::readCounters(m_counters); }

ImageRgb resolveFilm(const std::vector<glm::vec4>& sums, uint32_t width, uint32_t height) {
    ImageRgb image;
    image.width = width;
    image.height = height;
    const uint64_t pixels = uint64_t(width) * height;
    image.pixels.resize(pixels * 3);
    for (uint64_t i = 0; i < pixels; ++i) {
        const glm::vec4 s = sums[i];
        const float inv = s.w > 0.0f ? 1.0f / s.w : 0.0f;
        image.pixels[3 * i + 0] = s.x * inv;
        image.pixels[3 * i + 1] = s.y * inv;
        image.pixels[3 * i + 2] = s.z * inv;
    }
    return image;
}

}  // namespace vkp
