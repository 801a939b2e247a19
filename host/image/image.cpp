#include "image/image.h"

#include <cmath>
#include <stdexcept>

namespace vkp {

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

double relativeMse(const ImageRgb& image, const ImageRgb& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("relativeMse: images differ in size");
    if (image.pixels.empty()) return 0.0;
    double sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const double d = double(image.pixels[i]) - reference.pixels[i];
        sum += d * d / (double(reference.pixels[i]) * reference.pixels[i] + 1e-2);
    }
    return sum / static_cast<double>(image.pixels.size());
}

}  // namespace vkp
