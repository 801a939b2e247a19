// --direct raster with and without skipping the shadow volumes of lights whose primary photons
// reach no cell the camera sees (lights/light_reach.h): the raster pass's time and lights,
// and the difference of the images. Renders at depth 1 (first vertex only) with one sample, where
// the image is the raster pass's direct light plus the emission seen: the difference is exactly the
// direct light of the skipped lights. `full` uses the light BVH (no skipping), `skip` the photon
// light cells; the two renders take turns (--repeat times) so a loaded machine slows both alike.
// Usage: build/bench/raster_skip_bench [SCENE] [--width W --height H --area-light-samples N
//          --repeat R --light-photons N --device D]
#include <cmath>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "median.h"
#include "image/metrics.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/stopwatch.h"
#include "vk/context.h"

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton raster light skipping benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/rooms-10x10.gltf";
    uint32_t width = 160, height = 120, areaSamples = 16, repeat = 3;
    std::string device;
    LightSampling photon{LightSampler::Photon};
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--width", width)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--area-light-samples", areaSamples)->capture_default_str();
    app.add_option("--repeat", repeat)->capture_default_str();
    app.add_option("--light-photons", photon.cellPhotons)->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        fmt::print("scene: {}, {}x{}, {} area samples per triangle, device: {}\n", scenePath, width, height,
                   areaSamples, context.deviceName());
        Renderer full(context, scene, {LightSampler::Bvh});
        const auto prepare = Clock::now();
        Renderer skip(context, scene, photon);
        fmt::print("photon light cells set-up ({} paths): {:.2f} s\n", photon.cellPhotons, secondsSince(prepare));
        FrameSettings s;
        s.width = width;
        s.height = height;
        s.samplesPerPixel = 1;
        s.maxDepth = 1;
        s.seed = 1;
        s.direct = DirectLight::Raster;
        s.areaLightSamples = areaSamples;
        std::vector<double> fullPass, skipPass, fullFrame, skipFrame;
        RenderResult a, b;
        for (uint32_t r = 0; r < repeat; ++r) {
            auto start = Clock::now();
            a = full.render<PathIntegrator>(s);
            fullFrame.push_back(secondsSince(start));
            fullPass.push_back(a.stats.get<double>("raster.seconds"));
            start = Clock::now();
            b = skip.render<PathIntegrator>(s);
            skipFrame.push_back(secondsSince(start));
            skipPass.push_back(b.stats.get<double>("raster.seconds"));
        }
        const double meanFull = meanLuminance(a.image);
        double maxDiff = 0.0;
        uint64_t differing = 0;
        const size_t pixels = a.image.pixels.size() / 3;
        for (size_t i = 0; i < pixels; ++i) {
            const float* p = &a.image.pixels[3 * i];
            const float* q = &b.image.pixels[3 * i];
            const double d = std::abs(luminance(p[0], p[1], p[2]) - luminance(q[0], q[1], q[2]));
            maxDiff = std::max(maxDiff, d);
            if (d > 1e-3 * meanFull) ++differing;
        }
        fmt::print("| | raster lights | skipped scene lights | raster pass (s, median) | render (s, median) |\n"
                   "|---|---|---|---|---|\n");
        fmt::print("| full (bvh) | {} | - | {:.3f} | {:.3f} |\n", a.stats.get<uint64_t>("raster.lights"),
                   bench::median(fullPass), bench::median(fullFrame));
        fmt::print("| skip (photon) | {} | {} | {:.3f} | {:.3f} |\n", b.stats.get<uint64_t>("raster.lights"),
                   b.stats.get<uint64_t>("raster.skippedLights"), bench::median(skipPass), bench::median(skipFrame));
        fmt::print("image: relMSE(skip vs full) {:.3g}, mean luminance {:.5g} vs {:.5g}, largest pixel difference "
                   "{:.3g} ({:.3g} x the mean), pixels differing by > 0.1 % of the mean: {} of {}\n",
                   relativeMse(b.image, a.image), meanLuminance(b.image), meanFull, maxDiff, maxDiff / meanFull,
                   differing, pixels);
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
