#include "image/metrics.h"

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {

double relativeMse(const ImageRgb& image, const ImageRgb& reference) {
    if (image.width != reference.width || image.height != reference.height ||
        image.pixels.size() != reference.pixels.size())
        throw InputError(fmt::format("relative MSE: the images differ in size ({}x{} vs {}x{})", image.width,
                                     image.height, reference.width, reference.height));
    if (image.pixels.empty()) return 0.0;
    double sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const double a = image.pixels[i], b = reference.pixels[i];
        sum += (a - b) * (a - b) / (b * b + 1e-2);
    }
    return sum / static_cast<double>(image.pixels.size());
}

std::array<double, 3> meanRadiance(const ImageRgb& image) {
    std::array<double, 3> sum{0.0, 0.0, 0.0};
    const size_t count = image.pixels.size() / 3;
    if (count == 0) return sum;
    for (size_t i = 0; i < count * 3; ++i) sum[i % 3] += image.pixels[i];
    for (double& s : sum) s /= static_cast<double>(count);
    return sum;
}

double meanLuminance(const ImageRgb& image) {
    const auto [r, g, b] = meanRadiance(image);
    return luminance(r, g, b);  // luminance is linear, so the mean of Y is Y of the mean
}

ImageRgb blockMeans(const ImageRgb& image, uint32_t block) {
    ImageRgb out;
    out.width = image.width / block;
    out.height = image.height / block;
    out.pixels.assign(size_t(out.width) * out.height * 3, 0.0f);
    for (uint32_t y = 0; y < out.height * block; ++y)
        for (uint32_t x = 0; x < out.width * block; ++x)
            for (int c = 0; c < 3; ++c)
                out.pixels[3 * ((y / block) * out.width + x / block) + c] +=
                    image.pixels[3 * (size_t(y) * image.width + x) + c] / float(block * block);
    return out;
}

}  // namespace vkp
