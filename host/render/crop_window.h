// A part of the image (--crop, --tile): a rectangle of pixels of the full frame. A part renders
// with the full frame's camera, size and seed, so each pixel gets the same rays and random
// streams as in a full render, and `vkphoton merge` joins parts into the full image bit for bit
// (docs/distributed-rendering.md). The GPU computes the rows the window spans, as one contiguous
// range of pixel indices (cropPixels); the image keeps only the window.
#pragma once

#include <cstdint>
#include <string>

#include "image/image.h"
#include "vk/compute_kernel.h"

namespace vkp {

struct CropWindow {
    uint32_t x0 = 0;  // first column
    uint32_t y0 = 0;  // first row (top)
    uint32_t x1 = 0;  // one past the last column
    uint32_t y1 = 0;  // one past the last row

    uint32_t width() const { return x1 - x0; }
    uint32_t height() const { return y1 - y0; }
    bool operator==(const CropWindow&) const = default;
    // "x0,y0,x1,y1", as --crop takes it and the EXR header stores it.
    std::string text() const;
};

// --crop X0,Y0,X1,Y1: four integers (x1, y1 exclusive); InputError naming `flag` otherwise.
CropWindow parseCrop(const std::string& text, const std::string& flag = "--crop");
// --tile I/N: the I-th of N bands of whole rows (1 <= I <= N <= height), rows
// floor((I-1) H / N) .. floor(I H / N) - 1; InputError naming --tile otherwise.
CropWindow parseTile(const std::string& text, uint32_t width, uint32_t height);
// InputError naming `flag` unless the window is non-empty and inside a width x height image.
void checkCrop(const CropWindow& crop, uint32_t width, uint32_t height, const std::string& flag = "--crop");

// The pixel indices (y * width + x) from the window's first pixel to its last: what the GPU computes.
vk::ItemRange cropPixels(const CropWindow& crop, uint32_t width);
// The window's pixels of a full-frame image.
ImageRgb cropImage(const ImageRgb& image, const CropWindow& crop);

}  // namespace vkp
