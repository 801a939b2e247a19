#include "view/display_pass.h"

#include <algorithm>

#include "shared/photon_render.glsl"

namespace vkp {

std::vector<glm::vec4> displayLattice(ViewTransform view) {
    constexpr uint32_t n = gpu::kDisplayLatticeSize;
    std::vector<float> radiance(n);
    for (uint32_t i = 0; i < n; ++i) radiance[i] = gpu::displayLatticeRadiance(i);
    std::vector<glm::vec4> lattice(size_t(n) * n * n);
    for (uint32_t z = 0; z < n; ++z)
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const glm::vec3 shown = applyViewTransform(glm::vec3(radiance[x], radiance[y], radiance[z]), view);
                lattice[(size_t(z) * n + y) * n + x] =
                    glm::vec4(linearToSrgb(shown.x), linearToSrgb(shown.y), linearToSrgb(shown.z), 1.0f);
            }
    return lattice;
}

DisplayPass::DisplayPass(vk::Context& context, uint32_t width, uint32_t height, const std::vector<glm::vec4>& lattice)
    : m_width(width), m_height(height),
      m_lattice(vk::makeStorageBuffer(context, "display lattice", lattice)),
      m_mask(context, "display mask", std::max<VkDeviceSize>(16, VkDeviceSize(width) * height * sizeof(uint32_t)),
             vk::kStorageUsage),
      m_noProgressive(context, "no progressive estimates", sizeof(gpu::SppmPixel), vk::kStorageUsage),
      m_linear(context, "display linear image", VkDeviceSize(width) * height * sizeof(glm::vec4), vk::kStorageUsage),
      m_pixels(context, "display pixels", VkDeviceSize(width) * height * sizeof(uint32_t), vk::kStorageUsage),
      m_kernel(context) {
    m_kernel.bind(gpu::kDisplayLatticeBinding, m_lattice);
    m_kernel.bind(gpu::kDisplayMaskBinding, m_mask);
    m_kernel.bind(gpu::kDisplayLinearBinding, m_linear);
    m_kernel.bind(gpu::kDisplayPixelBinding, m_pixels);
}

void DisplayPass::setMask(const std::vector<uint8_t>& mask) {
    m_hasMask = !mask.empty();
    if (!m_hasMask) return;
    std::vector<uint32_t> words(size_t(m_width) * m_height);
    for (size_t i = 0; i < words.size() && i < mask.size(); ++i) words[i] = mask[i] != 0;
    m_mask.upload(words);
}

void DisplayPass::record(VkCommandBuffer cmd, const vk::Buffer& filmSums, const vk::Buffer* progressive,
                         uint32_t passes, float exposureScale, bool bgra) {
    // Rebound per record: the session's film and integrator change with the scene and the
    // integrator (the presenter waits for each submission, so no set is in use meanwhile).
    m_kernel.bind(gpu::kDisplayFilmBinding, filmSums);
    m_kernel.bind(gpu::kDisplayProgressiveBinding, progressive ? *progressive : m_noProgressive);
    gpu::DisplayParams params{};
    params.width = m_width;
    params.height = m_height;
    params.passes = static_cast<float>(std::max(1u, passes));
    params.exposureScale = exposureScale;
    params.hasProgressive = progressive != nullptr;
    params.hasMask = m_hasMask;
    params.bgra = bgra;
    m_kernel.record(cmd, uint64_t(m_width) * m_height, params);
    vk::computeBarrier(cmd);
}

ImageRgb DisplayPass::linearImage() const {
    const std::vector<glm::vec4> pixels = m_linear.download<glm::vec4>();
    ImageRgb image;
    image.width = m_width;
    image.height = m_height;
    image.pixels.resize(pixels.size() * 3);
    for (size_t i = 0; i < pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[3 * i + c] = pixels[i][c];
    return image;
}

}  // namespace vkp
