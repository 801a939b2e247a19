#include "app/compare_command.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "image/exr.h"
#include "util/errors.h"
#include "util/printable.h"

namespace vkp {
namespace {

// The names joined by ", ", escaped for the terminal (a channel or attribute name is the file's).
std::string listed(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return printable(text);
}

std::map<std::string, std::string> asMap(const ExrAttributes& attributes) {
    return {attributes.begin(), attributes.end()};
}

std::vector<std::string> differingAttributes(const ExrAttributes& a, const ExrAttributes& b) {
    const auto ma = asMap(a), mb = asMap(b);
    std::vector<std::string> names;
    for (const auto& [name, value] : ma) {
        const auto it = mb.find(name);
        if (it == mb.end() || it->second != value) names.push_back(name);
    }
    for (const auto& [name, value] : mb)
        if (!ma.count(name)) names.push_back(name);
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

ExrComparison compareExrs(const std::filesystem::path& a, const std::filesystem::path& b) {
    ExrAttributes attributesA, attributesB;
    const ImageRgb imageA = readExr(a, &attributesA);
    const ImageRgb imageB = readExr(b, &attributesB);
    ExrComparison result;
    result.width = imageA.width;
    result.height = imageA.height;
    result.sameSize = imageA.width == imageB.width && imageA.height == imageB.height;
    result.differingAttributes = differingAttributes(attributesA, attributesB);

    const std::vector<std::string> namesA = exrChannelNames(a), namesB = exrChannelNames(b);
    for (const std::string& name : namesA)
        if (std::find(namesB.begin(), namesB.end(), name) != namesB.end()) result.channels.push_back(name);
        else result.channelsInOneOnly.push_back("A: " + name);
    for (const std::string& name : namesB)
        if (std::find(namesA.begin(), namesA.end(), name) == namesA.end()) result.channelsInOneOnly.push_back("B: " + name);
    if (!result.sameSize) return result;

    const size_t pixels = size_t(imageA.width) * imageA.height;
    std::vector<bool> pixelDiffers(pixels, false);
    size_t firstPixel = pixels;  // the first difference in scan-line order, then channel order
    for (const std::string& name : result.channels) {
        const std::vector<float> va = readExrChannel(a, name), vb = readExrChannel(b, name);
        result.values += pixels;
        for (size_t i = 0; i < pixels; ++i) {
            if (std::bit_cast<uint32_t>(va[i]) == std::bit_cast<uint32_t>(vb[i])) continue;
            ++result.differingValues;
            pixelDiffers[i] = true;
            if (std::isfinite(va[i]) && std::isfinite(vb[i]))
                result.largestDifference = std::max(result.largestDifference, std::abs(double(va[i]) - double(vb[i])));
            if (i < firstPixel) {
                firstPixel = i;
                result.firstDifference = fmt::format("({}, {}) {}: {:.9g} vs {:.9g}", i % imageA.width,
                                                     i / imageA.width, name, va[i], vb[i]);
            }
        }
    }
    result.differingPixels = uint64_t(std::count(pixelDiffers.begin(), pixelDiffers.end(), true));
    return result;
}

int runCompare(const CompareCommandOptions& options) {
    const ExrComparison c = compareExrs(options.a, options.b);
    if (!options.quiet) {
        const std::string names = printable(options.a.string()) + " and " + printable(options.b.string());
        if (c.pixelsIdentical()) {
            fmt::print("{}: pixels identical, bit for bit ({}x{}, {} channels: {})\n", names, c.width, c.height,
                       c.channels.size(), listed(c.channels));
        } else if (!c.sameSize) {
            fmt::print("{}: pixels differ: the images have different sizes\n", names);
        } else {
            fmt::print("{}: pixels differ", names);
            if (!c.channelsInOneOnly.empty())
                fmt::print(": channels in one file only ({})", listed(c.channelsInOneOnly));
            if (c.differingValues > 0)
                fmt::print(": {} of {} values in {} of {} pixels; first at {}; largest difference {:.3g}",
                           c.differingValues, c.values, c.differingPixels, uint64_t(c.width) * c.height,
                           printable(c.firstDifference), c.largestDifference);
            fmt::print("\n");
        }
        if (!c.differingAttributes.empty())
            fmt::print("header attributes that differ: {}\n", listed(c.differingAttributes));
    }
    return c.pixelsIdentical() ? kExitOk : kExitImagesDiffer;
}

}  // namespace vkp
