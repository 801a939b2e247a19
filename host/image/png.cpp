#include "image/png.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <stb/stb_image_write.h>

#include "image/atomic_file.h"
#include "util/errors.h"

namespace vkp {

float tonemapAces(float x) {
    x = std::max(0.0f, x);
    const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

float linearToSrgb(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

uint8_t toDisplayByte(float linear, float exposure) {
    if (!std::isfinite(linear)) linear = 0.0f;
    return static_cast<uint8_t>(std::lround(255.0f * linearToSrgb(tonemapAces(linear * exposure))));
}

void writePng(const std::filesystem::path& path, const ImageRgb& image, float exposure) {
    std::vector<uint8_t> bytes(image.pixels.size());
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = toDisplayByte(image.pixels[i], exposure);
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        if (!stbi_write_png(temp.c_str(), static_cast<int>(image.width), static_cast<int>(image.height), 3,
                            bytes.data(), static_cast<int>(image.width * 3)))
            throw std::runtime_error("PNG encoder failed");
    });
}

}  // namespace vkp
