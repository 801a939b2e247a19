// Environment-map importance sampling against uniform sphere sampling (docs/environment.md): the
// path tracer on a scene lit by a sun-and-sky map, next-event directions drawn from the map's
// luminance x sin(theta) distribution (map) or uniformly over the sphere (uniform), both with MIS
// against BSDF sampling. Prints seconds and relMSE against a high-sample reference (rendered
// with map sampling) at 1..max spp, and the relMSE each reaches at equal time.
// Usage: build/bench/environment_bench [SCENE] [--env MAP] [--size N --reference-spp N
//                                      --reference FILE.exr --max-spp N --device D]
#include <cmath>
#include <string>

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
    CLI::App app{"vkphoton environment importance sampling benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/spheres-outdoor.gltf";
    std::string envPath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/sun-sky.hdr";
    uint32_t size = 96, referenceSpp = 4096, maxSpp = 256;
    std::string device, referencePath;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--env", envPath, "environment map")->capture_default_str();
    app.add_option("--size", size, "image size")->capture_default_str();
    app.add_option("--reference-spp", referenceSpp, "reference samples per pixel")->capture_default_str();
    app.add_option("--reference", referencePath, "reference EXR: read if it exists, else rendered and written");
    app.add_option("--max-spp", maxSpp, "largest sample count per method")->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        vk::Context context({false, device});
        Scene mapScene = loadGltf(scenePath);
        Scene uniformScene = loadGltf(scenePath);
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
        fmt::print("{:>8} {:>6} {:>9} {:>10}\n", "method", "spp", "seconds", "relMSE");
        struct Point { double seconds, relMse; };
        std::vector<Point> curves[2];
        for (int m = 0; m < 2; ++m) {
            Renderer& renderer = m == 0 ? mapRenderer : uniformRenderer;
            for (uint32_t spp = 1; spp <= maxSpp; spp *= 2) {
                FrameSettings s = base;
                s.samplesPerPixel = spp;
                s.seed = 7;
                const auto start = Clock::now();
                const ImageRgb image = renderer.render<PathIntegrator>(s).image;
                const double seconds = secondsSince(start);
                const double error = relativeMse(image, reference);
                curves[m].push_back({seconds, error});
                fmt::print("{:>8} {:>6} {:>9.3f} {:>10.5f}\n", m == 0 ? "map" : "uniform", spp, seconds, error);
            }
        }
        // Equal time: the uniform curve's relMSE interpolated (log-log) at each map point's time.
        fmt::print("equal time (uniform interpolated at the map's seconds):\n");
        for (const Point& p : curves[0]) {
            const auto& u = curves[1];
            for (size_t k = 1; k < u.size(); ++k)
                if (u[k - 1].seconds <= p.seconds && p.seconds <= u[k].seconds) {
                    const double t = std::log(p.seconds / u[k - 1].seconds) / std::log(u[k].seconds / u[k - 1].seconds);
                    const double e = std::exp(std::log(u[k - 1].relMse) + t * std::log(u[k].relMse / u[k - 1].relMse));
                    fmt::print("  {:.3f} s: map {:.5f}, uniform {:.5f} ({:.1f}x)\n", p.seconds, p.relMse, e, e / p.relMse);
                }
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
