#include "image/png.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

// The encoder is compiled here, static to this file: libstb.so (which tinygltf links) exports
// the same names, and two exported definitions would leave which one runs to the link order.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO  // we only encode to memory; atomic_file does the file I/O
#include <stb/stb_image_write.h>

#include "image/atomic_file.h"
#include "util/errors.h"

namespace vkp {
namespace {

double srgbOetf(double x) {
    if (!(x > 0.0)) return 0.0;
    if (x >= 1.0) return 1.0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

void appendBytes(void* context, void* data, int size) {
    const char* bytes = static_cast<const char*>(data);
    static_cast<std::string*>(context)->append(bytes, bytes + size);
}

}  // namespace

float tonemapAces(float x) {
    if (!(x > 0.0f)) return 0.0f;
    // The curve passes 1 near x = 7.24 and stays above it, so this changes nothing but avoids
    // inf / inf = NaN where x * x overflows (x > ~1.8e19, or +inf).
    if (x >= 16.0f) return 1.0f;
    constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return std::min((x * (a * x + b)) / (x * (c * x + d) + e), 1.0f);
}

float linearToSrgb(float x) { return static_cast<float>(srgbOetf(x)); }

uint8_t linearToSrgb8(float x) {
    // In double so that the rounding to 8 bits does not suffer a float rounding first.
    return static_cast<uint8_t>(std::lround(255.0 * srgbOetf(x)));
}

uint8_t toDisplayByte(float linear, float exposure) { return linearToSrgb8(tonemapAces(linear * exposure)); }

void writePng(const std::filesystem::path& path, const ImageRgb& image, float exposure) {
    writeBytesAtomically(path, pngBytes(path, image, exposure));
}

std::string pngBytes(const std::filesystem::path& path, const ImageRgb& image, float exposure) {
    if (!(std::isfinite(exposure) && exposure > 0.0f))
        throw InputError(fmt::format("exposure must be positive and finite, not {}", exposure));
    if (!isWellFormed(image))
        throw RuntimeError(fmt::format("cannot write {}: the image is empty or has {} values for {}x{} pixels",
                                       path.string(), image.pixels.size(), image.width, image.height));
    // stb_image_write sizes its buffers with int: (3 * width + 1) * height bytes must fit.
    if ((uint64_t(image.width) * 3 + 1) * image.height > uint64_t(INT_MAX) / 2)
        throw RuntimeError(fmt::format("cannot write {}: {}x{} is too large for the PNG encoder", path.string(),
                                       image.width, image.height));
    std::vector<uint8_t> display(image.pixels.size());
    std::transform(image.pixels.begin(), image.pixels.end(), display.begin(),
                   [exposure](float v) { return toDisplayByte(v, exposure); });
    std::string encoded;
    if (!stbi_write_png_to_func(appendBytes, &encoded, static_cast<int>(image.width), static_cast<int>(image.height),
                                3, display.data(), static_cast<int>(image.width * 3)))
        throw RuntimeError(fmt::format("cannot write {}: the PNG encoder failed", path.string()));
    return encoded;
}

}  // namespace vkp
