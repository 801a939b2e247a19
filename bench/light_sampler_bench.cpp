// Next-event light choice and triangle sampling against each other: relMSE against a high-sample
// path-traced reference, per sample count (per-sample error) or at equal time, for each method:
//   area         power selection, emissive triangles by area (the plain baseline)
//   power        power selection, emissive triangles by solid angle
//   bvh          the light BVH, emissive triangles by solid angle
//   photon       photon light cells mixed with the BVH (default --light-cell-* settings)
// The reference is rendered with --reference-method (bvh by default: unbiased, and far less noisy
// than power where most lights are occluded).
// Usage: build/bench/light_sampler_bench [SCENE] [--size N --reference-spp N --reference FILE.exr
//          --spp 4,16,64 --seconds S --methods area,power,bvh,photon --reference-method M --seeds K --device D]
//          --integrator path|photon --photons N --caustic-photons N]
// With --seconds, each method renders for that long (--time-limit) and reports the spp it reached.
// Methods take turns per seed (seed 1 of every method, then seed 2...), so that the load of a shared
// machine falls on all of them alike. --integrator photon renders with the photon integrator (its
// visible points' next-event estimation uses the sampler; the photon maps are built in each render
// and count in its time); the reference is always path traced.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image/metrics.h"
#include "reference_image.h"
#include "render/path_integrator.h"
#include "photon/photon_integrator.h"
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
    std::string device, referencePath, referenceMethod = "bvh", integrator = "path";
    PhotonIntegratorSettings photon;
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
    app.add_option("--integrator", integrator, "path or photon")->check(CLI::IsMember({"path", "photon"}))
        ->capture_default_str();
    app.add_option("--photons", photon.globalPaths, "--integrator photon: global map paths")->capture_default_str();
    app.add_option("--caustic-photons", photon.causticPaths, "--integrator photon: caustic map paths")
        ->capture_default_str();
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
        struct Row { std::string method; std::unique_ptr<Renderer> renderer; double error = 0, time = 0, spp = 0; };
        std::vector<Row> rows;
        for (const std::string& method : methods) {
            const auto prepare = Clock::now();
            rows.push_back({method, std::make_unique<Renderer>(context, scene, sampling.at(method))});
            const double prepareSeconds = secondsSince(prepare);  // light BVH, photon cells
            if (prepareSeconds > 0.05) fmt::print("({} set-up: {:.2f} s)\n", method, prepareSeconds);
        }
        fmt::print("integrator: {}\n| method | spp | s | relMSE |\n|---|---|---|---|\n", integrator);
        const std::vector<uint32_t> counts = seconds > 0.0 ? std::vector<uint32_t>{1u << 20} : spps;
        for (uint32_t spp : counts) {
            for (Row& row : rows) row.error = row.time = row.spp = 0.0;
            for (uint32_t k = 0; k < seeds; ++k) {
                for (Row& row : rows) {
                    FrameSettings s = base;
                    s.samplesPerPixel = spp;
                    s.timeLimitSeconds = seconds;
                    s.seed = 1 + k;
                    const auto start = Clock::now();
                    const RenderResult r = integrator == "photon" ? row.renderer->render<PhotonIntegrator>(s, photon)
                                                                  : row.renderer->render<PathIntegrator>(s);
                    row.time += secondsSince(start);
                    row.error += relativeMse(r.image, reference);
                    row.spp += double(r.stats.get<uint64_t>("counters.samplesPerPixel"));
                }
            }
            for (const Row& row : rows) {
                fmt::print("| {} | {:.0f} | {:.2f} | {:.5f} |\n", row.method, row.spp / seeds, row.time / seeds,
                           row.error / seeds);
            }
            std::fflush(stdout);
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
