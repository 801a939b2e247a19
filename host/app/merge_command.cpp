#include "app/merge_command.h"

#include <map>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "image/atomic_file.h"
#include "image/exposure.h"
#include "image/png.h"
#include "image/view_transform.h"
#include "render/crop_window.h"
#include "render/stats.h"
#include "util/errors.h"
#include "util/printable.h"

namespace vkp {
namespace {

constexpr const char* kFullWidth = "vkphoton/fullWidth";
constexpr const char* kFullHeight = "vkphoton/fullHeight";
constexpr const char* kCrop = "vkphoton/crop";
constexpr const char* kPartSettings = "vkphoton/partSettings";
// Attributes every part of one render shares (besides kPartSettings, which holds them too).
constexpr const char* kShared[] = {"vkphoton/scene", "vkphoton/integrator", "vkphoton/spp", "vkphoton/seed",
                                   "vkphoton/maxDepth", kFullWidth, kFullHeight, kPartSettings};

struct Part {
    std::filesystem::path path;
    ImageRgb image;
    std::map<std::string, std::string> attributes;
    CropWindow crop;
};

std::string name(const std::filesystem::path& path) { return printable(path.string()); }

uint32_t parseSize(const Part& part, const char* key) {
    const std::string& text = part.attributes.at(key);
    try {
        size_t used = 0;
        const unsigned long value = std::stoul(text, &used);
        if (used == text.size() && value >= 1 && value <= 16384) return static_cast<uint32_t>(value);
    } catch (const std::exception&) {
    }
    throw InputError(fmt::format("{}: {} '{}' is not an image size", name(part.path), key, printable(text)));
}

Part readPart(const std::filesystem::path& path) {
    Part part;
    part.path = path;
    ExrAttributes attributes;
    part.image = readExr(path, &attributes);
    for (const auto& [key, value] : attributes) part.attributes[key] = value;
    for (const char* key : kShared)
        if (!part.attributes.count(key))
            throw InputError(fmt::format("{}: not a part of a render: its header has no {} (render parts with "
                                         "--tile or --crop)", name(path), key));
    if (!part.attributes.count(kCrop))
        throw InputError(fmt::format("{}: not a part of a render: its header has no {} (render parts with --tile "
                                     "or --crop)", name(path), kCrop));
    part.crop = parseCrop(part.attributes.at(kCrop), name(path) + ": " + kCrop);
    checkCrop(part.crop, parseSize(part, kFullWidth), parseSize(part, kFullHeight), name(path) + ": " + kCrop);
    if (part.image.width != part.crop.width() || part.image.height != part.crop.height())
        throw InputError(fmt::format("{}: the image is {}x{}, its window {} is {}x{}", name(path), part.image.width,
                                     part.image.height, part.crop.text(), part.crop.width(), part.crop.height()));
    if (part.attributes.count("vkphoton/partial") && part.attributes.at("vkphoton/partial") == "true")
        throw InputError(fmt::format("{}: a partial render ({}): its pixels are not those of a complete one",
                                     name(path), printable(part.attributes["vkphoton/stopReason"])));
    return part;
}

// The PNG's display settings as the parts' headers recorded them (the defaults where they cannot be read).
DisplaySettings displayOf(const Part& part) {
    DisplaySettings display;
    const auto tonemap = part.attributes.find("vkphoton/tonemap");
    if (tonemap != part.attributes.end())
        for (const auto& [label, view] : viewTransformChoices())
            if (label == tonemap->second) display.view = view;
    const auto exposure = part.attributes.find("vkphoton/exposure");
    if (exposure != part.attributes.end()) {
        try {
            display.exposureEv = std::stof(exposure->second);
            display.check();
        } catch (const std::exception&) {
            display.exposureEv = DisplaySettings().exposureEv;
        }
    }
    // Metered parts: the joined image is metered again, as the full render would have been.
    const auto mode = part.attributes.find("vkphoton/exposureMode");
    display.autoExposure = mode != part.attributes.end() && mode->second == "auto";
    return display;
}

}  // namespace

ExrAttributes partAttributes(const FrameSettings& frame, const Stats& stats) {
    if (!frame.crop) return {};
    nlohmann::json settings = nlohmann::json::object();
    for (const auto& [key, value] : stats.entries())
        if (key.rfind("settings.", 0) == 0 && key != "settings.timeLimit")
            std::visit([&](const auto& v) { settings[key] = v; }, value);
    return {{kFullWidth, std::to_string(frame.width)},
            {kFullHeight, std::to_string(frame.height)},
            {kCrop, frame.crop->text()},
            {kPartSettings, settings.dump()}};
}

int runMerge(const MergeCommandOptions& options) {
    const std::filesystem::path& exrPath = options.output;
    if (exrPath.extension() != ".exr")
        throw InputError(fmt::format("-o {}: the output must end in .exr (a .png is written beside it)", name(exrPath)));
    std::filesystem::path pngPath = exrPath;
    pngPath.replace_extension(".png");
    checkWritable(exrPath);
    checkWritable(pngPath);
    if (options.parts.empty()) throw InputError("merge: no parts given");

    std::vector<Part> parts;
    for (const auto& path : options.parts) {
        parts.push_back(readPart(path));
        const Part& first = parts.front();
        const Part& part = parts.back();
        for (const char* key : kShared)
            if (part.attributes.at(key) != first.attributes.at(key))
                throw InputError(fmt::format("{}: not a part of the same render as {}: {} is '{}' there, '{}' here",
                                             name(part.path), name(first.path), key,
                                             printable(first.attributes.at(key)), printable(part.attributes.at(key))));
    }
    const uint32_t width = parseSize(parts.front(), kFullWidth);
    const uint32_t height = parseSize(parts.front(), kFullHeight);

    // Which part covers each pixel: none, or exactly one.
    std::vector<int> owner(size_t(width) * height, -1);
    ImageRgb full = makeImage(width, height);
    for (size_t i = 0; i < parts.size(); ++i) {
        const Part& part = parts[i];
        for (uint32_t y = part.crop.y0; y < part.crop.y1; ++y)
            for (uint32_t x = part.crop.x0; x < part.crop.x1; ++x) {
                int& o = owner[size_t(y) * width + x];
                if (o >= 0)
                    throw InputError(fmt::format("{}: its window {} overlaps {}'s window {} at pixel ({}, {})",
                                                 name(part.path), part.crop.text(), name(parts[o].path),
                                                 parts[o].crop.text(), x, y));
                o = static_cast<int>(i);
                const float* from = part.image.at(x - part.crop.x0, y - part.crop.y0);
                float* to = full.at(x, y);
                to[0] = from[0];
                to[1] = from[1];
                to[2] = from[2];
            }
    }
    uint64_t missing = 0;
    std::optional<std::pair<uint32_t, uint32_t>> firstMissing;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            if (owner[size_t(y) * width + x] < 0) {
                ++missing;
                if (!firstMissing) firstMissing = {x, y};
            }
    if (missing > 0)
        throw InputError(fmt::format("merge: the parts leave {} of the {}x{} pixels uncovered, the first at ({}, {}): "
                                     "a part is missing",
                                     missing, width, height, firstMissing->first, firstMissing->second));

    // The first part's header, less what belongs to a part, and the parts' summed times.
    ExrAttributes attributes;
    double renderSeconds = 0.0;
    for (const Part& part : parts) {
        const auto it = part.attributes.find("vkphoton/renderSeconds");
        if (it != part.attributes.end()) renderSeconds += std::atof(it->second.c_str());
    }
    const auto backdrop = parts.front().attributes.find(kExposureBackgroundAttribute);
    const DisplaySettings display =
        resolveExposure(displayOf(parts.front()), full,
                        backdrop == parts.front().attributes.end() ? std::nullopt : parseExposureBackground(backdrop->second));
    for (const auto& [key, value] : parts.front().attributes)
        if (key.rfind("vkphoton/", 0) == 0 && key != kCrop && key != kFullWidth && key != kFullHeight &&
            key != kPartSettings && key != "vkphoton/totalSeconds" && key != "vkphoton/exposure")
            attributes.emplace_back(key, value);
    if (parts.front().attributes.count("vkphoton/exposure"))
        attributes.emplace_back("vkphoton/exposure", fmt::format("{}", display.exposureEv));
    attributes.emplace_back("vkphoton/renderSeconds", fmt::format("{:.3f}", renderSeconds));
    attributes.emplace_back("vkphoton/mergedParts", std::to_string(parts.size()));
    writeFilesTogether({{exrPath, exrBytes(exrPath, full, attributes)},
                        {pngPath, pngBytes(pngPath, full, display)}});
    if (!options.quiet)
        fmt::print(stderr, "merged {} parts into {} and {} ({}x{})\n", parts.size(), name(exrPath), name(pngPath), width,
                   height);
    return kExitOk;
}

}  // namespace vkp
