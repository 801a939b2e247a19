// The film every integrator adds its samples to: per pixel the RGB sum and the sample count
// (vec4), written by exactly one invocation per pixel so accumulation is deterministic, and a
// few counters the camera-path shaders keep (dropped non-finite samples, path segments).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "passes/path_trace_pass.h"
#include "vk/buffer.h"

namespace vkp {

class Film {
public:
    Film(vk::Context& context, uint32_t width, uint32_t height);

    const vk::Buffer& sums() const { return m_sums; }
    // The camera-path kernels' counters (slots gpu::kPathTraceCounter*, passes/path_trace_pass.h).
    const vk::Buffer& counters() const { return m_counters; }
    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }

    // Zeroes sums and counters; ends with them visible to compute shaders.
    void recordClear(VkCommandBuffer cmd) const;
    // Read-backs after the last sample's submission: the mean per pixel, and the counters.
    ImageRgb resolve() const;
    PathTraceCounters readCounters() const;

private:
    uint32_t m_width;
    uint32_t m_height;
    vk::Buffer m_sums;
    vk::Buffer m_counters;
};

// Per-pixel sums (rgb, sample count) as an image of means.
ImageRgb resolveFilm(const std::vector<glm::vec4>& sums, uint32_t width, uint32_t height);

}  // namespace vkp
