// vkphoton's closest-hit ray rates against Embree 3's on the same scene, cores and ray
// distributions, in one run: camera rays through every pixel of a raySize² image (coherent) and
// one cosine-distributed diffuse bounce ray from each camera hit (incoherent). Embree traces them
// one ray at a time (rtcIntersect1, the "single-ray" figure production renderers quote) on as many
// threads as the machine has; vkphoton runs bench/shaders/ray_throughput.comp on the device. Usage:
//   build/bench/embree_bench [SCENE] [--ray-size N --repeat R --threads T --device D]
// Prints a Markdown table for docs/benchmarks.md. Built only when Debian's libembree-dev is found.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <random>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "embree_scene.h"
#include "gpu_ray_rates.h"
#include "median.h"
#include "gpu_scene/scene_buffers.h"
#include "render/frame.h"
#include "scene/gltf_loader.h"
#include "shared/sampling.glsl"
#include "vk/context.h"
#include "vk/shader_registry.h"

namespace vkp::embedded {
extern const vk::ShaderEntry* const vkphoton_bench_shaders_table[];
}

namespace {

using namespace vkp;
using Clock = std::chrono::steady_clock;

struct Ray {
    glm::vec3 origin;
    glm::vec3 dir;
    float tnear;
};

// Runs `work(i)` for i in [0, count) on `threads` threads, items handed out in blocks of 256.
template <class Work>
double timeParallel(size_t count, unsigned threads, const Work& work) {
    std::atomic<size_t> next{0};
    const auto start = Clock::now();
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (size_t begin; (begin = next.fetch_add(256)) < count;)
                for (size_t i = begin; i < std::min(count, begin + 256); ++i) work(i);
        });
    for (auto& thread : pool) thread.join();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"vkphoton against Embree: closest-hit ray rates on the same scene"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/cornell-box.gltf";
    uint32_t raySize = 1024, repeat = 5;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::string device;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--ray-size", raySize, "image side: raySize² camera rays per run")->capture_default_str();
    app.add_option("--repeat", repeat, "repetitions (the median is reported)")->capture_default_str();
    app.add_option("--threads", threads, "Embree's threads")->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);

    try {
        vk::registerShaderTable(embedded::vkphoton_bench_shaders_table);
        const Scene scene = loadGltf(scenePath);
        const float tnear = 1e-4f * std::max(1e-3f, glm::length(scene.bounds.extent()));

        // The same camera rays as the device kernel (one jittered sample per pixel).
        const gpu::GpuCamera camera = makeGpuCamera(chooseCamera(scene, -1), raySize, raySize);
        const size_t pixels = size_t(raySize) * raySize;
        std::vector<Ray> cameraRays(pixels);
        std::mt19937 rng(1);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        for (size_t p = 0; p < pixels; ++p) {
            const glm::vec2 pixel(float(p % raySize) + uniform(rng), float(p / raySize) + uniform(rng));
            cameraRays[p] = {gpu::cameraRayOrigin(camera, raySize, raySize, pixel),
                             gpu::cameraRayDirection(camera, raySize, raySize, pixel), 0.0f};
        }

        const auto buildStart = Clock::now();
        const bench::EmbreeScene embree(scene);
        const double buildSeconds = std::chrono::duration<double>(Clock::now() - buildStart).count();

        // Bounce rays from the camera hits, generated once (not timed), then traced.
        std::vector<Ray> bounceRays(pixels);
        std::vector<uint8_t> hit(pixels, 0);
        timeParallel(pixels, threads, [&](size_t p) {
            float t;
            glm::vec3 n;
            const Ray& r = cameraRays[p];
            if (!embree.intersect(r.origin, r.dir, r.tnear, t, n)) return;
            hit[p] = 1;
            if (glm::dot(n, r.dir) > 0.0f) n = -n;
            glm::vec3 tangent, bitangent;
            gpu::orthonormalBasis(n, tangent, bitangent);
            std::mt19937 local(uint32_t(p) * 9781u + 7u);
            const glm::vec2 u(uniform(local), uniform(local));
            bounceRays[p] = {r.origin + t * r.dir, gpu::toWorld(gpu::sampleCosineHemisphere(u), tangent, bitangent, n),
                             tnear};
        });
        std::vector<Ray> bounces;
        for (size_t p = 0; p < pixels; ++p)
            if (hit[p]) bounces.push_back(bounceRays[p]);

        auto timeRays = [&](const std::vector<Ray>& rays) {
            std::vector<double> times;
            std::atomic<uint64_t> sink{0};
            for (uint32_t r = 0; r < repeat + 1; ++r) {
                const double s = timeParallel(rays.size(), threads, [&](size_t i) {
                    float t;
                    glm::vec3 n;
                    if (embree.intersect(rays[i].origin, rays[i].dir, rays[i].tnear, t, n))
                        sink.fetch_add(1, std::memory_order_relaxed);
                });
                if (r > 0) times.push_back(s);
            }
            return rays.size() / bench::median(times) / 1e6;
        };
        const double embreeCamera = timeRays(cameraRays);
        const double embreeBounce = timeRays(bounces);

        vk::Context context({false, device});
        const SceneArrays arrays = buildSceneArrays(scene);
        const SceneBuffers buffers(context, arrays);
        const bench::RayRates gpu = bench::measureGpuRayRates(context, scene, buffers, raySize, repeat);

        fmt::print("scene: {} ({} triangles), {}x{} camera rays, {} bounce rays (Embree) / {} (vkphoton), "
                   "Embree {} threads (BVH build {:.3f} s), vkphoton device: {}\n",
                   scenePath, scene.triangles.size(), raySize, raySize, bounces.size(), gpu.bounceRays, threads,
                   buildSeconds, context.deviceName());
        fmt::print("| rays | vkphoton | Embree 3 single-ray | vkphoton / Embree |\n|---|---|---|---|\n");
        fmt::print("| camera (closest hit) | {:.2f} Mrays/s | {:.2f} Mrays/s | {:.0f} % |\n", gpu.cameraMrays,
                   embreeCamera, 100.0 * gpu.cameraMrays / embreeCamera);
        fmt::print("| diffuse bounce (closest hit) | {:.2f} Mrays/s | {:.2f} Mrays/s | {:.0f} % |\n",
                   gpu.bounceMrays, embreeBounce, 100.0 * gpu.bounceMrays / embreeBounce);
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
}
