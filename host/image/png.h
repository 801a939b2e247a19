// 8-bit sRGB PNG output through the display transform of image/view_transform.h.
#pragma once

#include <filesystem>
#include <string>

#include "image/image.h"
#include "image/view_transform.h"

namespace vkp {

// Writes an RGB 8-bit PNG of toDisplayBytes(pixel, display) per pixel, atomically (see
// atomic_file.h). Throws InputError when the display settings fail their check, RuntimeError
// naming the path on any other failure (including an image that is not well-formed).
void writePng(const std::filesystem::path& path, const ImageRgb& image, const DisplaySettings& display = {});
// The bytes writePng would write (`path` only names it in messages).
std::string pngBytes(const std::filesystem::path& path, const ImageRgb& image, const DisplaySettings& display = {});

// What the PNG shows, in numbers: the mean of its 8-bit values over 255 (0 black, 1 white), and
// the share of pixels with a channel at 255 (blown out).
struct DisplayStatistics {
    double mean = 0.0;
    double saturated = 0.0;
};
DisplayStatistics displayStatistics(const ImageRgb& image, const DisplaySettings& display = {});

}  // namespace vkp
