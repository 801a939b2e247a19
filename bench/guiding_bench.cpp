// Guided path tracing against cosine sampling and BSDF+NEE path tracing (Jensen 1995's experiment):
// relMSE against a high-sample path-traced reference at 1...max spp, with seconds, for
//   cosine   BSDF (cosine) sampling only, no next-event estimation
//   path     the path tracer: next-event estimation + BSDF sampling, MIS
//   paper    guided, the paper's method: a k-nearest gather per vertex, grid only (mix 1)
//   per-vertex  a k-nearest gather per vertex, mixed with the BSDF like the default (no cache)
//   guided   vkphoton's default: guiding cache, one-sample MIS with the BSDF (mix 0.5), one row
//            per --mixes value and --guide-rr choice (Russian roulette by throughput or by the guide)
// Usage: build/bench/guiding_bench [SCENE] [--size N --reference-spp N --reference FILE.exr
//                                   --max-spp N --max-seconds S --mixes M,.. --guide-rr off,on --device D]
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image/metrics.h"
#include "reference_image.h"
#include "guiding/guided_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/stopwatch.h"
#include "vk/context.h"

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton guided path tracing benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/cornell-ceiling.gltf";
    uint32_t size = 64, referenceSpp = 16384, maxSpp = 512;
    double maxSeconds = 60.0;
    std::string device, referencePath, only;
    std::vector<float> mixes{0.5f};
    std::vector<std::string> roulettes{"off", "on"};
    uint32_t adapt = 0;
    uint32_t guidePhotons = GuideSettings{}.photons;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--size", size, "image size")->capture_default_str();
    app.add_option("--reference-spp", referenceSpp, "path-traced reference samples per pixel")->capture_default_str();
    app.add_option("--reference", referencePath, "reference EXR: read if it exists, else rendered and written");
    app.add_option("--max-spp", maxSpp, "largest sample count per method")->capture_default_str();
    app.add_option("--max-seconds", maxSeconds, "stop a method's curve once a render takes longer")->capture_default_str();
    app.add_option("--mixes", mixes, "guide-mix values of the default (cached) guided rows")->delimiter(',');
    app.add_option("--guide-rr", roulettes, "--guide-rr choices of the guided rows")->delimiter(',')
        ->check(CLI::IsMember({"off", "on"}));
    app.add_option("--guide-adapt", adapt, "--guide-adapt of the guided rows")->capture_default_str();
    app.add_option("--guide-photons", guidePhotons, "guiding map paths")->capture_default_str();
    app.add_option("--only", only, "run only this method (cosine, path, paper, guided)");
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        Renderer renderer(context, scene);
        FrameSettings base;
        base.width = size;
        base.height = size;
        GuideSettings baseGuide;
        baseGuide.photons = guidePhotons;
        fmt::print("scene: {}, {}x{}, device: {}\n", scenePath, size, size, context.deviceName());
        const ImageRgb reference = bench::referenceImage(renderer, base, referenceSpp, referencePath);
        struct Method {
            const char* name;
            FrameSettings settings;
            bool guided = false;
            GuideSettings guide;
        };
        std::vector<Method> methods;
        FrameSettings cosine = base;
        cosine.nextEventEstimation = false;
        methods.push_back({"cosine", cosine});
        methods.push_back({"path", base});
        GuideSettings paper = baseGuide;
        paper.cache = false;
        paper.mix = 1.0f;
        methods.push_back({"paper", base, true, paper});
        GuideSettings perVertex = paper;  // the cache's alternative at the same mix
        perVertex.mix = mixes.front();
        methods.push_back({"per-vertex", base, true, perVertex});
        std::vector<std::string> guidedNames;
        for (float mix : mixes)
            for (const std::string& rr : roulettes) guidedNames.push_back(fmt::format("guided mix {} rr {}", mix, rr));
        for (size_t i = 0; i < guidedNames.size(); ++i) {
            GuideSettings guided = baseGuide;
            guided.mix = mixes[i / roulettes.size()];
            guided.roulette = roulettes[i % roulettes.size()] == "on";
            guided.adaptPhotons = adapt;
            methods.push_back({guidedNames[i].c_str(), base, true, guided});
        }
        fmt::print("\n| method | spp | seconds | relMSE | segments per path |\n|---|---|---|---|---|\n");
        for (const Method& m : methods) {
            if (!only.empty() && std::string(m.name).rfind(only, 0) != 0) continue;
            for (uint32_t spp = 1; spp <= maxSpp; spp *= 2) {
                FrameSettings s = m.settings;
                s.samplesPerPixel = spp;
                s.seed = 1;
                const RenderResult r = m.guided ? renderer.render<GuidedIntegrator>(s, m.guide)
                                                : renderer.render<PathIntegrator>(s);
                const auto seconds = r.stats.get<double>("timings.renderSeconds");
                fmt::print("| {} | {} | {:.2f} | {:.5f} | {:.3f} |\n", m.name, spp, seconds,
                           relativeMse(r.image, reference),
                           r.stats.get<double>("counters.pathSegments") / r.stats.get<double>("counters.cameraPaths"));
                std::fflush(stdout);
                if (seconds > maxSeconds) break;
            }
        }
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
}
