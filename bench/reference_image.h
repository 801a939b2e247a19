// The high-sample path-traced reference the convergence benchmarks compare against: read from
// `path` when that file exists (references take minutes), else rendered and written there.
#pragma once

#include <filesystem>

#include <fmt/format.h>

#include "image/exr.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "util/stopwatch.h"

namespace vkp::bench {

inline ImageRgb referenceImage(Renderer& renderer, FrameSettings settings, uint32_t samplesPerPixel,
                               const std::filesystem::path& path) {
    if (!path.empty() && std::filesystem::exists(path)) {
        fmt::print("reference: {}\n", path.string());
        return readExr(path);
    }
    settings.samplesPerPixel = samplesPerPixel;
    settings.seed = 1000;  // independent of the measured runs' seed
    const auto start = Clock::now();
    ImageRgb reference = renderer.render<PathIntegrator>(settings).image;
    fmt::print("reference: path tracer, {} spp, {:.0f} s\n", samplesPerPixel, secondsSince(start));
    if (!path.empty()) writeExr(path, reference);
    return reference;
}

}  // namespace vkp::bench
