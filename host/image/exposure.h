// Automatic exposure of the PNG (`--exposure auto`, the render command's default): the EV that
// brings the image's trimmed log-average luminance to mid grey, as a camera's averaging meter
// and a game engine's eye adaptation do. The EXR is never scaled; this only picks the PNG's EV.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "image/view_transform.h"

namespace vkp {

// The metering rule (docs/output.md, "Automatic exposure"):
//   1. the Rec.709 luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of every pixel;
//   2. only pixels with a finite Y > 0 count ("lit" pixels): a black background where no
//      environment is seen says nothing about how bright the scene is; nor, under a constant
//      environment (the default white sky, --env V), do pixels equal to its radiance: the sky
//      seen directly is the backdrop, not the subject (an averaging meter pointed at a white
//      backdrop darkens the subject). If that leaves no pixel, the backdrop is metered;
//   3. of the n lit pixels sorted by Y, the darkest and the brightest floor(0.05 n) are dropped
//      (visible lamps, highlights, noise-black shadows);
//   4. L = 2^(mean of log2 Y over the rest), the geometric mean;
//   5. EV = log2(0.18 / L), clamped to [-64, 64] (--exposure's range). An image without a lit
//      pixel gets EV 0.
constexpr float kMeterMidGrey = 0.18f;
constexpr double kMeterTrimFraction = 0.05;

struct ExposureMeter {
    float ev = 0.0f;               // the chosen exposure
    double logAverage = 0.0;       // L of step 4 (0 without lit pixels)
    size_t litPixels = 0;          // n of step 3
    size_t backgroundPixels = 0;   // pixels of the constant environment left out
    size_t meteredPixels = 0;      // n - 2 floor(0.05 n)
};

// The rule above over a well-formed image. Deterministic: the same pixels give the same EV.
// `background`: the constant environment's radiance, whose pixels step 2 leaves out.
ExposureMeter meterExposure(const ImageRgb& image, const std::optional<glm::vec3>& background = std::nullopt);

// `display` with its EV metered from `image` when autoExposure is set (the flag stays set, so
// the EXR header can say the EV was metered); unchanged otherwise.
DisplaySettings resolveExposure(const DisplaySettings& display, const ImageRgb& image,
                                const std::optional<glm::vec3>& background = std::nullopt);

// "auto" or a number of stops, as --exposure takes it: InputError naming --exposure otherwise
// (NaN, infinities and values outside [-64, 64] included).
DisplaySettings parseExposure(const std::string& text, DisplaySettings display);

// The EXR header's record of the PNG's exposure: vkphoton/exposure (the EV applied, shortest
// round-trip decimal) and vkphoton/exposureMode ("auto" or "fixed"); metered with a
// `background`, vkphoton/exposureBackground "R,G,B" too, so `vkphoton merge` meters the joined
// parts by the same rule.
std::vector<std::pair<std::string, std::string>> exposureAttributes(
    const DisplaySettings& display, const std::optional<glm::vec3>& background = std::nullopt);
constexpr const char* kExposureBackgroundAttribute = "vkphoton/exposureBackground";
// "R,G,B" as exposureAttributes writes it; nullopt for anything else.
std::optional<glm::vec3> parseExposureBackground(const std::string& text);

}  // namespace vkp
