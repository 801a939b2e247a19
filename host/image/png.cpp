#include "image/png.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <thread>
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

void appendBytes(void* context, void* data, int size) {
    const char* bytes = static_cast<const char*>(data);
    static_cast<std::string*>(context)->append(bytes, bytes + size);
}

}  // namespace

void writePng(const std::filesystem::path& path, const ImageRgb& image, const DisplaySettings& display) {
    writeBytesAtomically(path, pngBytes(path, image, display));
}

DisplayStatistics displayStatistics(const ImageRgb& image, const DisplaySettings& display) {
    DisplayStatistics s;
    const size_t pixels = image.pixels.size() / 3;
    if (pixels == 0) return s;
    double sum = 0.0;
    size_t saturated = 0;
    for (size_t i = 0; i < 3 * pixels; i += 3) {
        const auto rgb = toDisplayBytes(glm::vec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]), display);
        sum += double(rgb[0]) + rgb[1] + rgb[2];
        saturated += rgb[0] == 255 || rgb[1] == 255 || rgb[2] == 255;
    }
    s.mean = sum / (3.0 * 255.0 * double(pixels));
    s.saturated = double(saturated) / double(pixels);
    return s;
}

std::string pngBytes(const std::filesystem::path& path, const ImageRgb& image, const DisplaySettings& display) {
    display.check();
    if (!isWellFormed(image))
        throw RuntimeError(fmt::format("cannot write {}: the image is empty or has {} values for {}x{} pixels",
                                       path.string(), image.pixels.size(), image.width, image.height));
    // stb_image_write sizes its buffers with int: (3 * width + 1) * height bytes must fit.
    if ((uint64_t(image.width) * 3 + 1) * image.height > uint64_t(INT_MAX) / 2)
        throw RuntimeError(fmt::format("cannot write {}: {}x{} is too large for the PNG encoder", path.string(),
                                       image.width, image.height));
    // AgX costs about 1 s per megapixel on one core: bands of rows on every core.
    std::vector<uint8_t> bytes(image.pixels.size());
    const auto convert = [&](size_t begin, size_t end) {
        for (size_t i = 3 * begin; i < 3 * end; i += 3) {
            const auto rgb = toDisplayBytes(glm::vec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]), display);
            std::copy(rgb.begin(), rgb.end(), bytes.begin() + i);
        }
    };
    const size_t pixels = size_t(image.width) * image.height;
    const size_t bands = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, std::max<size_t>(1, pixels / 65536));
    std::vector<std::thread> workers;
    for (size_t b = 1; b < bands; ++b) workers.emplace_back(convert, pixels * b / bands, pixels * (b + 1) / bands);
    convert(0, pixels / bands);
    for (std::thread& w : workers) w.join();
    std::string encoded;
    if (!stbi_write_png_to_func(appendBytes, &encoded, static_cast<int>(image.width), static_cast<int>(image.height),
                                3, bytes.data(), static_cast<int>(image.width * 3)))
        throw RuntimeError(fmt::format("cannot write {}: the PNG encoder failed", path.string()));
    return encoded;
}

}  // namespace vkp
