#include "image/image.h"

#include <cmath>

namespace vkp {

ImageRgb makeImage(uint32_t width, uint32_t height) {
    return ImageRgb{width, height, std::vector<float>(size_t(width) * height * 3, 0.0f)};
}

bool isWellFormed(const ImageRgb& image) {
    return image.width > 0 && image.height > 0 && image.pixels.size() == size_t(image.width) * image.height * 3;
}

double meanValue(const ImageRgb& image) {
    if (image.pixels.empty()) return 0.0;
    double sum = 0.0;
    for (float v : image.pixels) sum += v;
    return sum / static_cast<double>(image.pixels.size());
}

bool allFinite(const ImageRgb& image) {
    for (float v : image.pixels)
        if (!std::isfinite(v)) return false;
    return true;
}

}  // namespace vkp
