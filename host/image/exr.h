// OpenEXR output: linear float32 RGB with string header attributes (settings, timings, partial).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace vkp {

using ExrAttributes = std::vector<std::pair<std::string, std::string>>;

// An extra FLOAT channel beside R, G, B (the --aov layers): one value per pixel, row-major.
struct ExrChannel {
    std::string name;
    std::vector<float> values;
};

// Writes channels R, G, B as FLOAT with ZIP compression, each attribute as a string header
// attribute (a later duplicate name wins). Writes atomically (see atomic_file.h); throws
// RuntimeError naming the path on failure, including an image that is not well-formed or an
// attribute name that OpenEXR rejects (empty, too long, or a standard non-string attribute).
// The bytes writeExr would write (RuntimeError naming `path` when the image cannot be encoded).
std::string exrBytes(const std::filesystem::path& path, const ImageRgb& image, const ExrAttributes& attributes = {},
                     const std::vector<ExrChannel>& extra = {});
void writeExr(const std::filesystem::path& path, const ImageRgb& image, const ExrAttributes& attributes = {});

// Reads the R, G, B channels (half, float or uint, converted to float; alpha and other channels
// ignored) of a scan-line or tiled EXR, and its string attributes into `attributes` (sorted by
// name, as OpenEXR keeps them). Throws InputError naming the path when the file cannot be read or lacks R, G or B.
ImageRgb readExr(const std::filesystem::path& path, ExrAttributes* attributes = nullptr);

// The names of an EXR's channels and one channel's values (InputError when it has none of that name).
std::vector<std::string> exrChannelNames(const std::filesystem::path& path);
std::vector<float> readExrChannel(const std::filesystem::path& path, const std::string& name);

}  // namespace vkp
