// Photon tracing throughput: photon paths traced per second and photons stored per second.
//   build/bench/photon_bench [SCENE] [--paths N --max-deposits K --repeat R --device D]
#include <algorithm>
#include <chrono>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "gpu_scene/scene_buffers.h"
#include "photon/photon_tracer.h"
#include "scene/gltf_loader.h"
#include "vk/context.h"

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton photon tracing throughput benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/cornell-glass.gltf";
    uint32_t paths = 500000, maxDeposits = 8, repeat = 5;
    std::string device;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--paths", paths, "photon paths per run")->capture_default_str();
    app.add_option("--max-deposits", maxDeposits)->capture_default_str();
    app.add_option("--repeat", repeat, "runs after a warm-up (the median is reported)")->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        const SceneArrays arrays = buildSceneArrays(scene);
        const SceneBuffers buffers(context, arrays);
        PhotonTracer tracer(context, scene, arrays, buffers);
        PhotonSettings settings;
        settings.paths = paths;
        settings.maxDeposits = maxDeposits;
        std::vector<double> times;
        PhotonCounters counters;
        for (uint32_t r = 0; r <= repeat; ++r) {
            settings.firstPath = r * paths;
            const auto start = std::chrono::steady_clock::now();
            counters = tracer.trace(settings);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (r > 0) times.push_back(s);
        }
        std::sort(times.begin(), times.end());
        const double median = times[times.size() / 2];
        const uint64_t stored = counters.storedCaustic + counters.storedGlobal + counters.storedPrimary;
        fmt::print("scene: {} ({} triangles), {} paths, device: {}\n", scenePath, scene.triangles.size(), paths,
                   context.deviceName());
        fmt::print("| measure | value |\n|---|---|\n");
        fmt::print("| photon paths traced | {:.2f} M/s |\n", paths / median / 1e6);
        fmt::print("| photons stored | {:.2f} M/s ({:.2f} per path) |\n", stored / median / 1e6, double(stored) / paths);
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
}
