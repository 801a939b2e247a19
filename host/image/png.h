// Tonemapped 8-bit sRGB PNG output.
#pragma once

#include <cstdint>
#include <filesystem>

#include "image/image.h"

namespace vkp {

// ACES filmic curve fitted by Narkowicz (2015), per channel, for linear input >= 0.
float tonemapAces(float x);
// The exact piecewise sRGB transfer function (IEC 61966-2-1), input clamped to [0, 1].
float linearToSrgb(float x);
// Linear radiance to an 8-bit sRGB code value: exposure, tonemap, OETF, rounding.
uint8_t toDisplayByte(float linear, float exposure = 1.0f);

// Writes atomically (temporary file + rename); throws RuntimeError naming the path on failure.
void writePng(const std::filesystem::path& path, const ImageRgb& image, float exposure = 1.0f);

}  // namespace vkp
