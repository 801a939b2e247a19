// Next-event light choice and triangle sampling against each other: relMSE against a high-sample
// path-traced reference, per sample count (per-sample error) or at equal time, for each method:
//   area         power selection, emissive triangles by area (the behaviour before issue 16)
//   power        power selection, emissive triangles by solid angle
//   bvh          the light BVH, emissive triangles by solid angle
//   photon       photon light cells mixed with the BVH (default --light-cell-* settings)
// The reference is rendered with --reference-method (bvh by default: unbiased, and far less noisy
// than power where most lights are occluded).
// Usage: build/bench/light_sampler_bench [SCENE] [--size N --reference-spp N --reference FILE.exr
//          --spp 4,16,64 --seconds S --methods area,power,bvh,photon --reference-method M --seeds K --device D]
// With --seconds, each method renders for that long (--time-limit) and reports the spp it reached.
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image/metrics.h"
#include "reference_image.h"
#include "render/integrators/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/stopwatch.h"
#include "vk/context.h"

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton light sampler benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/cornell-box.gltf";
    uint32_t size = 64, referenceSpp = 4096, seeds = 1, maxDepth = 16;
    double seconds = 0.0;
    std::vector<uint32_t> spps{4, 16, 64};
    std::vector<std::string> methods{"area", "power", "bvh"};
    std::string device, referencePath, referenceMethod = "bvh";
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--size", size, "image size")->capture_default_str();
    app.add_option("--reference-spp", referenceSpp, "path-traced reference samples per pixel")->capture_default_str();
    app.add_option("--reference", referencePath, "reference EXR: read if it exists, else rendered and written");
    app.add_option("--spp", spps, "sample counts")->delimiter(',');
    app.add_option("--seconds", seconds, "equal time: render each method this long instead of --spp");
    app.add_option("--methods", methods, "area, power, bvh")->delimiter(',')
        ->check(CLI::IsMember({"area", "power", "bvh", "photon"}));
    app.add_option("--reference-method", referenceMethod, "light sampling of the reference")
        ->check(CLI::IsMember({"area", "power", "bvh", "photon"}))
        ->capture_default_str();
    app.add_option("--seeds", seeds, "independent renders per row (relMSE averaged)")->capture_default_str();
    app.add_option("--max-depth", maxDepth)->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        FrameSettings base;
        base.width = size;
        base.height = size;
        base.maxDepth = maxDepth;
        fmt::print("scene: {}, {}x{}, device: {}\n", scenePath, size, size, context.deviceName());
        const std::map<std::string, LightSampling> sampling{
            {"area", {LightSampler::Power, TriangleSampling::Area}},
            {"power", {LightSampler::Power, TriangleSampling::SolidAngle}},
            {"bvh", {LightSampler::Bvh, TriangleSampling::SolidAngle}},
            {"photon", {LightSampler::Photon, TriangleSampling::SolidAngle}}};
        ImageRgb reference;
        {
            Renderer renderer(context, scene, sampling.at(referenceMethod));
            reference = bench::referenceImage(renderer, base, referenceSpp, referencePath);
        }
        fmt::print("| method | spp | s | relMSE |\n|---|---|---|---|\n");
        for (const std::string& method : methods) {
            const auto prepare = Clock::now();
            Renderer renderer(context, scene, sampling.at(method));
            const double prepareSeconds = secondsSince(prepare);  // light BVH, photon cells
            if (prepareSeconds > 0.05) fmt::print("({} set-up: {:.2f} s)\n", method, prepareSeconds);
            auto row = [&](uint32_t spp, double limit) {
                double error = 0.0, time = 0.0, done = 0.0;
                for (uint32_t k = 0; k < seeds; ++k) {
                    FrameSettings s = base;
                    s.samplesPerPixel = spp;
                    s.timeLimitSeconds = limit;
                    s.seed = 1 + k;
                    const auto start = Clock::now();
                    const RenderResult r = renderer.render<PathIntegrator>(s);
                    time += secondsSince(start);
                    error += relativeMse(r.image, reference);
                    done += double(r.stats.get<uint64_t>("counters.samplesPerPixel"));
                }
                fmt::print("| {} | {:.0f} | {:.2f} | {:.5f} |\n", method, done / seeds, time / seeds, error / seeds);
                std::fflush(stdout);
            };
            if (seconds > 0.0) {
                row(1u << 20, seconds);
            } else {
                for (uint32_t spp : spps) row(spp, 0.0);
            }
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
