// Tonemapped 8-bit sRGB PNG output, and the display transform it uses.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "image/image.h"

namespace vkp {

// ACES filmic curve fitted by Narkowicz (2015), (x(2.51x + 0.03)) / (x(2.43x + 0.59) + 0.14),
// clamped to [0, 1]; applied per channel. Monotonic; NaN and x <= 0 give 0, +inf gives 1.
float tonemapAces(float x);
// The exact piecewise sRGB OETF (IEC 61966-2-1): 12.92x up to 0.0031308, else
// 1.055x^(1/2.4) - 0.055. Input clamped to [0, 1]; NaN gives 0.
float linearToSrgb(float x);
// linearToSrgb scaled to 0..255 and rounded to nearest: 0 -> 0, 1 -> 255.
uint8_t linearToSrgb8(float x);
// Linear radiance to an 8-bit sRGB code value: exposure scale, tonemap, OETF, rounding.
uint8_t toDisplayByte(float linear, float exposure = 1.0f);

// Writes an RGB 8-bit PNG of toDisplayByte(value, exposure) per channel, atomically (see
// atomic_file.h). Throws InputError when `exposure` is not positive and finite, RuntimeError
// naming the path on any other failure (including an image that is not well-formed).
// The bytes writePng would write.
std::string pngBytes(const std::filesystem::path& path, const ImageRgb& image, float exposure = 1.0f);
void writePng(const std::filesystem::path& path, const ImageRgb& image, float exposure = 1.0f);

}  // namespace vkp
