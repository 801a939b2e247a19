#include "image/exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {

namespace {

// A pixel whose every sample saw the constant environment: the film's average of equal values,
// equal to it up to the rounding of the sums.
bool isBackground(const float* rgb, const glm::vec3& background) {
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(rgb[c] - background[c]) <= 1.0e-5f * background[c])) return false;
    return true;
}

}  // namespace

ExposureMeter meterExposure(const ImageRgb& image, const std::optional<glm::vec3>& background) {
    ExposureMeter meter;
    const size_t pixels = size_t(image.width) * image.height;
    std::vector<double> logY, backdrop;
    logY.reserve(pixels);
    for (size_t i = 0; i < pixels && 3 * i + 2 < image.pixels.size(); ++i) {
        const float* rgb = &image.pixels[3 * i];
        const double y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
        if (!(std::isfinite(y) && y > 0.0)) continue;
        if (background && isBackground(rgb, *background)) backdrop.push_back(std::log2(y));
        else logY.push_back(std::log2(y));
    }
    meter.backgroundPixels = backdrop.size();
    if (logY.empty()) {  // nothing but the backdrop: meter it
        logY.swap(backdrop);
        meter.backgroundPixels = 0;
    }
    meter.litPixels = logY.size();
    if (logY.empty()) return meter;
    std::sort(logY.begin(), logY.end());
    const size_t trim = static_cast<size_t>(std::floor(double(logY.size()) * kMeterTrimFraction));
    // Summed in sorted order: the result does not depend on how the pixels were laid out.
    double sum = 0.0;
    for (size_t i = trim; i < logY.size() - trim; ++i) sum += logY[i];
    meter.meteredPixels = logY.size() - 2 * trim;
    const double meanLog = sum / double(meter.meteredPixels);
    meter.logAverage = std::exp2(meanLog);
    meter.ev = static_cast<float>(std::clamp(std::log2(double(kMeterMidGrey)) - meanLog, -64.0, 64.0));
    return meter;
}

DisplaySettings resolveExposure(const DisplaySettings& display, const ImageRgb& image,
                                const std::optional<glm::vec3>& background) {
    DisplaySettings resolved = display;
    if (display.autoExposure) resolved.exposureEv = meterExposure(image, background).ev;
    return resolved;
}

DisplaySettings parseExposure(const std::string& text, DisplaySettings display) {
    if (text == "auto") {
        display.autoExposure = true;
        display.exposureEv = 0.0f;
        return display;
    }
    float ev = 0.0f;
    size_t used = 0;
    try {
        ev = std::stof(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (text.empty() || used != text.size())
        throw InputError(fmt::format("--exposure {}: not a number of stops or 'auto'", text));
    display.autoExposure = false;
    display.exposureEv = ev;
    display.check();  // NaN, infinities, |EV| > 64
    return display;
}

std::vector<std::pair<std::string, std::string>> exposureAttributes(const DisplaySettings& display,
                                                                    const std::optional<glm::vec3>& background) {
    std::vector<std::pair<std::string, std::string>> attributes{
        {"vkphoton/exposure", fmt::format("{}", display.exposureEv)},
        {"vkphoton/exposureMode", display.autoExposure ? "auto" : "fixed"}};
    if (display.autoExposure && background)
        attributes.emplace_back(kExposureBackgroundAttribute,
                                fmt::format("{},{},{}", background->x, background->y, background->z));
    return attributes;
}

std::optional<glm::vec3> parseExposureBackground(const std::string& text) {
    glm::vec3 rgb;
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const size_t end = k < 2 ? text.find(',', start) : text.size();
        if (end == std::string::npos) return std::nullopt;
        try {
            size_t used = 0;
            const std::string part = text.substr(start, end - start);
            rgb[k] = std::stof(part, &used);
            if (used != part.size() || !std::isfinite(rgb[k])) return std::nullopt;
        } catch (const std::exception&) {
            return std::nullopt;
        }
        start = end + 1;
    }
    return rgb;
}

}  // namespace vkp
