// A linear RGB float image (row-major, top row first) and simple statistics over it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vkp {

struct ImageRgb {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> pixels;  // 3 floats per pixel

    float* at(uint32_t x, uint32_t y) { return &pixels[3 * (size_t(y) * width + x)]; }
    const float* at(uint32_t x, uint32_t y) const { return &pixels[3 * (size_t(y) * width + x)]; }
};

// Mean over all pixels and channels.
double meanValue(const ImageRgb& image);
// True when no value is NaN or infinite.
bool allFinite(const ImageRgb& image);
// Relative MSE: mean over pixels and channels of (a - b)^2 / (b^2 + 1e-2); b is the reference.
double relativeMse(const ImageRgb& image, const ImageRgb& reference);

}  // namespace vkp
