// A linear RGB float image (row-major, top row first) and simple checks over it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vkp {

struct ImageRgb {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> pixels;  // 3 floats per pixel: R, G, B

    float* at(uint32_t x, uint32_t y) { return &pixels[3 * (size_t(y) * width + x)]; }
    const float* at(uint32_t x, uint32_t y) const { return &pixels[3 * (size_t(y) * width + x)]; }
};

// A black image of the given size.
ImageRgb makeImage(uint32_t width, uint32_t height);
// True when the image is non-empty and holds exactly width * height * 3 floats; the writers
// refuse anything else rather than read past the end of `pixels`.
bool isWellFormed(const ImageRgb& image);
// Mean over all pixels and channels.
double meanValue(const ImageRgb& image);
// True when no value is NaN or infinite.
bool allFinite(const ImageRgb& image);

}  // namespace vkp
