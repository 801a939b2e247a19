// The film every integrator adds its samples to: per pixel the RGB sum and the sample count
// (vec4), written by exactly one invocation per pixel so accumulation is deterministic, and a
// few counters the camera-path shaders keep (dropped non-finite samples, path segments).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "vk/buffer.h"

namespace vkp {

struct FilmCounters {
    uint64_t nonFiniteSamples = 0;  // samples that were NaN or infinite (dropped)
    uint64_t pathSegments = 0;      // rays traced from camera-path vertices (no shadow rays)
};

class Film {
public:
    Film(vk::Context& context, uint32_t width, uint32_t height);

    const vk::Buffer& sums() const { return m_sums; }
    // uint slots: 0 non-finite samples, 1 and 2 the low and high words of the path segments.
    const vk::Buffer& counters() const { return m_counters; }
    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }

    // Zeroes sums and counters; ends with them visible to compute shaders.
    void recordClear(VkCommandBuffer cmd) const;
    // Read-backs after the last sample's submission: the mean per pixel, and the counters.
    ImageRgb resolve() const;
    FilmCounters readCounters() const;

private:
    uint32_t m_width;
    uint32_t m_height;
    vk::Buffer m_sums;
    vk::Buffer m_counters;
};

// Per-pixel sums (rgb, sample count) as an image of means.
ImageRgb resolveFilm(const std::vector<glm::vec4>& sums, uint32_t width, uint32_t height);

}  // namespace vkp
