// Image statistics and comparisons used by tests, benchmarks and the stats JSON.
#pragma once

#include <array>
#include <cstdint>

#include "image/image.h"

namespace vkp {

// Relative MSE of `image` against `reference`: the mean over pixels and channels of
// (a - b)^2 / (b^2 + 1e-2). The 1e-2 keeps near-black reference pixels from dominating.
// Throws InputError when the sizes differ.
double relativeMse(const ImageRgb& image, const ImageRgb& reference);

// Mean R, G and B over all pixels (zeros for an empty image).
std::array<double, 3> meanRadiance(const ImageRgb& image);

// Luminance Y of linear Rec. 709 / sRGB primaries, the same weights as the shaders' luminance().
constexpr double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

// Mean luminance over all pixels (0 for an empty image).
double meanLuminance(const ImageRgb& image);

// The means over blocks of block x block pixels (rows and columns past the last whole block are
// left out): compares estimators' expected images with less of the per-pixel noise.
ImageRgb blockMeans(const ImageRgb& image, uint32_t block);

}  // namespace vkp
