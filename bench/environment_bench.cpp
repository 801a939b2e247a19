// Environment-map importance sampling against uniform sphere sampling (docs/environment.md): the
// path tracer on a scene lit by a sun-and-sky map, next-event directions drawn from the map's
// luminance x sin(theta) distribution (map) or uniformly over the sphere (uniform), both with MIS
// against BSDF sampling. Prints seconds and relMSE against a high-sample reference (rendered
// with map sampling) reached in equal render times. Every material becomes Lambert (base colour
// kept) unless --keep-materials: caustics from a small sun through glass, mirrors and smooth coats
// are found only by BSDF sampling and would dominate both errors.
// Usage: build/bench/environment_bench [SCENE] [--env MAP] [--size N --reference-spp N
//                                      --reference FILE.exr --seconds S,.. --keep-materials --device D]
#include <cmath>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image/metrics.h"
#include "lights/default_lighting.h"
#include "reference_image.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/stopwatch.h"
#include "vk/context.h"

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton environment importance sampling benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/spheres-outdoor.gltf";
    std::string envPath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/sun-sky.hdr";
    uint32_t size = 96, referenceSpp = 4096;
    std::vector<double> budgets{1.0, 2.0, 4.0, 8.0};
    bool keepMaterials = false;
    std::string device, referencePath;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--env", envPath, "environment map")->capture_default_str();
    app.add_option("--size", size, "image size")->capture_default_str();
    app.add_option("--reference-spp", referenceSpp, "reference samples per pixel")->capture_default_str();
    app.add_option("--reference", referencePath, "reference EXR: read if it exists, else rendered and written");
    app.add_option("--seconds", budgets, "time budgets per render")->delimiter(',');
    app.add_flag("--keep-materials", keepMaterials, "keep the scene's materials (else all Lambert: caustics from the "
                                                   "sun via glass, mirrors and smooth coats, which no light sampling "
                                                   "helps, would dominate both errors)");
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        vk::Context context({false, device});
        Scene mapScene = loadGltf(scenePath);
        if (!keepMaterials)
            for (Material& m : mapScene.materials) {
                m.transmission = 0.0f;  // Lambert, base colour kept
                m.metallic = 0.0f;
                m.ior = 1.0f;
            }
        Scene uniformScene = mapScene;
        std::string note;
        EnvironmentSettings env;
        env.value = envPath;
        applyEnvironment(mapScene, env, note);
        env.importanceSampling = false;
        applyEnvironment(uniformScene, env, note);
        Renderer mapRenderer(context, mapScene);
        Renderer uniformRenderer(context, uniformScene);
        FrameSettings base;
        base.width = size;
        base.height = size;
        fmt::print("scene: {}, env: {}, {}x{}, device: {}\n", scenePath, envPath, size, size, context.deviceName());
        const ImageRgb reference = bench::referenceImage(mapRenderer, base, referenceSpp, referencePath);
        // Equal time: each method renders for the same wall-clock budget (the sample loop stops at
        // --time-limit), then its relMSE against the reference.
        fmt::print("{:>8} {:>9} {:>6} {:>10}\n", "method", "seconds", "spp", "relMSE");
        for (double budget : budgets)
            for (int m = 0; m < 2; ++m) {
                Renderer& renderer = m == 0 ? mapRenderer : uniformRenderer;
                FrameSettings s = base;
                s.samplesPerPixel = 1u << 20;
                s.timeLimitSeconds = budget;
                s.seed = 7;
                const RenderResult r = renderer.render<PathIntegrator>(s);
                fmt::print("{:>8} {:>9.1f} {:>6} {:>10.5f}\n", m == 0 ? "map" : "uniform", budget,
                           r.stats.get<uint32_t>("counters.samplesPerPixel"), relativeMse(r.image, reference));
            }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
