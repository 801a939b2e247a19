// Path tracer throughput on a shipped scene: camera rays/s (coherent), diffuse bounce rays/s
// (incoherent), and path-tracer samples/s. Usage:
//   build/bench/path_tracer_bench [SCENE] [--width W --height H --spp N --repeat R --device D]
// Prints a Markdown table row set for docs/benchmarks.md.
#include <algorithm>
#include <chrono>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "gpu_ray_rates.h"
#include "median.h"
#include "gpu_scene/scene_buffers.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"
#include "vk/context.h"
#include "vk/shader_registry.h"

namespace vkp::embedded {
extern const vk::ShaderEntry* const vkphoton_bench_shaders_table[];
}

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton path tracer throughput benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/cornell-box.gltf";
    uint32_t width = 512, height = 512, spp = 16, repeat = 5, raySize = 1024;
    std::string device;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--width", width)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--spp", spp, "samples per pixel for the path tracer run")->capture_default_str();
    app.add_option("--ray-size", raySize, "image side for the ray-throughput runs (enough rays for stable timings)")
        ->capture_default_str();
    app.add_option("--repeat", repeat, "repetitions (the median is reported)")->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);

    try {
        vk::registerShaderTable(embedded::vkphoton_bench_shaders_table);
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        const SceneArrays arrays = buildSceneArrays(scene);
        const SceneBuffers buffers(context, arrays);
        const bench::RayRates rays = bench::measureGpuRayRates(context, scene, buffers, raySize, repeat);
        const double cameraMrays = rays.cameraMrays;
        const double bounceMrays = rays.bounceMrays;

        const uint64_t pixels = uint64_t(width) * height;
        Renderer renderer(context, scene);
        FrameSettings settings;
        settings.width = width;
        settings.height = height;
        settings.samplesPerPixel = spp;
        std::vector<double> renderTimes;
        std::vector<double> renderCpu;
        for (uint32_t r = 0; r < std::max(1u, repeat / 2); ++r) {
            const double cpuStart = bench::processCpuSeconds();
            renderTimes.push_back(renderer.render<PathIntegrator>(settings).stats.get<double>("timings.renderSeconds"));
            renderCpu.push_back(bench::processCpuSeconds() - cpuStart);
        }
        const double pathsPerSecond = pixels * spp / bench::median(renderTimes);
        const double pathsPerCpuSecond = pixels * spp / bench::median(renderCpu);

        fmt::print("scene: {} ({} triangles), rays at {}x{}, path tracer at {}x{}, device: {}\n", scenePath,
                   scene.triangles.size(), raySize, raySize, width, height, context.deviceName());
        fmt::print("| measure | value | per CPU-second (all threads) |\n|---|---|---|\n");
        fmt::print("| camera rays (closest hit) | {:.2f} Mrays/s | {:.2f} Mrays |\n", cameraMrays,
                   rays.cameraMraysPerCpuSecond);
        fmt::print("| diffuse bounce rays (closest hit) | {:.2f} Mrays/s | {:.2f} Mrays |\n", bounceMrays,
                   rays.bounceMraysPerCpuSecond);
        fmt::print("| path tracer, {} spp, max depth {} | {:.3f} Msamples/s | {:.3f} Msamples |\n", spp,
                   settings.maxDepth, pathsPerSecond / 1e6, pathsPerCpuSecond / 1e6);
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
}
