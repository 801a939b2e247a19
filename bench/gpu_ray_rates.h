// vkphoton's closest-hit ray rates on the device (bench/shaders/ray_throughput.comp): camera rays
// (coherent) and one cosine-distributed diffuse bounce from each camera hit (incoherent, timed as
// the difference of the two runs). Shared by path_tracer_bench and embree_bench.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "median.h"
#include "gpu_scene/scene_buffers.h"
#include "render/frame.h"
#include "shaders/bench_kernels.glsl"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/kernel.h"

namespace vkp::bench {

struct RayRates {
    double cameraMrays = 0.0;
    double bounceMrays = 0.0;
    uint64_t cameraRays = 0;
    uint64_t bounceRays = 0;  // camera rays that hit, each followed by one bounce ray
};

// `raySize`² camera rays per run; the median of `repeat` runs after one warm-up run.
inline RayRates measureGpuRayRates(vk::Context& context, const Scene& scene, const SceneBuffers& buffers,
                                   uint32_t raySize, uint32_t repeat) {
    using Clock = std::chrono::steady_clock;
    const uint64_t rayPixels = uint64_t(raySize) * raySize;
    vk::Buffer result(context, "hit counts", rayPixels * sizeof(uint32_t), vk::kStorageUsage);
    vk::Kernel<gpu::RayBenchKernel> kernel(context);
    kernel.bind(buffers.bindings());
    kernel.bind(gpu::kRayBenchResultBinding, result);
    gpu::RayBenchParams push{makeGpuCamera(chooseCamera(scene, -1), raySize, raySize), raySize, raySize, 0, 0};
    auto timeMode = [&](uint32_t mode) {
        std::vector<double> times;
        for (uint32_t r = 0; r < repeat + 1; ++r) {  // the first run warms up (JIT, caches)
            push.mode = mode;
            push.seed = r;
            const auto start = Clock::now();
            context.submitAndWait([&](VkCommandBuffer cmd) { kernel.record(cmd, rayPixels, push); });
            if (r > 0) times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
        }
        return median(times);
    };
    const double cameraSeconds = timeMode(0);
    const double bounceSeconds = timeMode(1);
    RayRates rates;
    rates.cameraRays = rayPixels;
    for (uint32_t h : result.download<uint32_t>()) rates.bounceRays += h >= 1;
    rates.cameraMrays = rayPixels / cameraSeconds / 1e6;
    rates.bounceMrays = rates.bounceRays / std::max(bounceSeconds - cameraSeconds, 1e-9) / 1e6;
    return rates;
}

}  // namespace vkp::bench
