// OpenEXR output: linear float32 RGB with string header attributes (settings, timings, partial).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace vkp {

using ExrAttributes = std::vector<std::pair<std::string, std::string>>;

// Writes atomically (temporary file + rename); throws RuntimeError naming the path on failure.
void writeExr(const std::filesystem::path& path, const ImageRgb& image, const ExrAttributes& attributes = {});

// Reads the R, G, B channels (half or float) of an EXR; string attributes into `attributes`.
ImageRgb readExr(const std::filesystem::path& path, ExrAttributes* attributes = nullptr);

}  // namespace vkp
