// Texture level of detail (do mipmaps chosen by ray cones pay? aliasing against cost): the path tracer with mipmaps chosen by ray cones (the default) and with level 0 only
// (--no-mipmaps), at the same sample counts, against a many-sample reference rendered without
// mipmaps (the supersampled texture: what both converge to). For each: relMSE against the
// reference (aliasing shows as error at few samples; the filter's blur as error that stays), the
// mean's ratio to the reference's (energy kept), and the seconds per render (the cost of the
// second level's texel fetches).
// Usage: build/bench/texture_lod_bench [SCENE] [--width W --height H --spp 1,4,16 --seeds K
//          --reference-spp N --reference FILE.exr --device D]
// Defaults: scenes/checker-floor.gltf (a textured floor to the horizon), 240x135. Modes take
// turns per seed, so the load of a shared machine falls on both alike.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "gpu_scene/texture_atlas.h"
#include "image/metrics.h"
#include "reference_image.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace {

double meanOf(const vkp::ImageRgb& image) {
    double sum = 0.0;
    for (const float v : image.pixels) sum += v;
    return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

}  // namespace

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton texture level-of-detail benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/checker-floor.gltf";
    uint32_t width = 240, height = 135, referenceSpp = 1024, seeds = 2;
    std::vector<uint32_t> spps{1, 4, 16};
    std::string device, referencePath;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--width", width)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--spp", spps, "sample counts")->delimiter(',');
    app.add_option("--seeds", seeds, "independent renders per row (averaged)")->capture_default_str();
    app.add_option("--reference-spp", referenceSpp, "reference samples per pixel (no mipmaps)")->capture_default_str();
    app.add_option("--reference", referencePath, "reference EXR: read if it exists, else rendered and written");
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        const Scene mipmapped = loadGltf(scenePath);
        Scene levelZero = mipmapped;
        disableMipmaps(levelZero);
        vk::Context context({false, device});
        FrameSettings base;
        base.width = width;
        base.height = height;
        fmt::print("scene: {}, {}x{}, device: {}\n", scenePath, width, height, context.deviceName());
        struct Mode { const char* name; Renderer renderer; double error = 0, mean = 0, time = 0; };
        Mode modes[] = {{"no mipmaps", Renderer(context, levelZero)}, {"mipmaps (ray cones)", Renderer(context, mipmapped)}};
        const ImageRgb reference = bench::referenceImage(modes[0].renderer, base, referenceSpp, referencePath);
        const double referenceMean = meanOf(reference);
        fmt::print("| textures | spp | s per render | relMSE | mean / reference |\n|---|---|---|---|---|\n");
        for (const uint32_t spp : spps) {
            for (Mode& m : modes) m.error = m.mean = m.time = 0.0;
            for (uint32_t k = 0; k < seeds; ++k)
                for (Mode& m : modes) {
                    FrameSettings s = base;
                    s.samplesPerPixel = spp;
                    s.seed = 1 + k;
                    const auto start = Clock::now();
                    const ImageRgb image = m.renderer.render<PathIntegrator>(s).image;
                    m.time += secondsSince(start);
                    m.error += relativeMse(image, reference);
                    m.mean += meanOf(image);
                }
            for (const Mode& m : modes)
                fmt::print("| {} | {} | {:.2f} | {:.5f} | {:.4f} |\n", m.name, spp, m.time / seeds, m.error / seeds,
                           m.mean / seeds / referenceMean);
            std::fflush(stdout);
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
