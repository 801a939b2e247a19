#include "render/crop_window.h"

#include <charconv>
#include <vector>

#include <fmt/format.h>

#include "util/errors.h"
#include "util/printable.h"

namespace vkp {
namespace {

// `text` split at `separator` into exactly `count` unsigned decimal integers below 2^31.
bool parseUnsigned(const std::string& text, char separator, size_t count, std::vector<uint32_t>& out) {
    out.clear();
    size_t start = 0;
    while (true) {
        const size_t end = text.find(separator, start);
        const std::string part = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        uint32_t value = 0;
        const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || ec != std::errc() || ptr != part.data() + part.size() || value >= (1u << 31)) return false;
        out.push_back(value);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return out.size() == count;
}

}  // namespace

std::string CropWindow::text() const { return fmt::format("{},{},{},{}", x0, y0, x1, y1); }

CropWindow parseCrop(const std::string& text, const std::string& flag) {
    std::vector<uint32_t> v;
    if (!parseUnsigned(text, ',', 4, v))
        throw InputError(fmt::format("{} {}: expected four pixel coordinates X0,Y0,X1,Y1", flag, printable(text)));
    return {v[0], v[1], v[2], v[3]};
}

CropWindow parseTile(const std::string& text, uint32_t width, uint32_t height) {
    std::vector<uint32_t> v;
    if (!parseUnsigned(text, '/', 2, v))
        throw InputError(fmt::format("--tile {}: expected I/N, the I-th of N tiles (1 <= I <= N)", printable(text)));
    const uint32_t index = v[0], count = v[1];
    if (index < 1 || index > count)
        throw InputError(fmt::format("--tile {}: I must be between 1 and N", printable(text)));
    if (count > height)
        throw InputError(fmt::format("--tile {}: {} tiles of whole rows need at least {} rows, the image has {}",
                                     printable(text), count, count, height));
    const auto row = [&](uint64_t i) { return static_cast<uint32_t>(i * height / count); };
    return {0, row(index - 1), width, row(index)};
}

void checkCrop(const CropWindow& crop, uint32_t width, uint32_t height, const std::string& flag) {
    if (crop.x0 >= crop.x1 || crop.y0 >= crop.y1)
        throw InputError(fmt::format("{} {}: the window is empty (X0 < X1 and Y0 < Y1 are needed)", flag, crop.text()));
    if (crop.x1 > width || crop.y1 > height)
        throw InputError(fmt::format("{} {}: outside the {}x{} image", flag, crop.text(), width, height));
}

vk::ItemRange cropPixels(const CropWindow& crop, uint32_t width) {
    const uint64_t first = uint64_t(crop.y0) * width + crop.x0;
    const uint64_t last = uint64_t(crop.y1 - 1) * width + crop.x1;  // one past the last pixel
    return {first, last - first};
}

ImageRgb cropImage(const ImageRgb& image, const CropWindow& crop) {
    ImageRgb out = makeImage(crop.width(), crop.height());
    for (uint32_t y = 0; y < crop.height(); ++y)
        for (uint32_t x = 0; x < crop.width(); ++x) {
            const float* from = image.at(crop.x0 + x, crop.y0 + y);
            float* to = out.at(x, y);
            to[0] = from[0];
            to[1] = from[1];
            to[2] = from[2];
        }
    return out;
}

}  // namespace vkp
