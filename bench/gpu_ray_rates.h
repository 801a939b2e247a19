// vkphoton's closest-hit ray rates on the device (bench/shaders/ray_throughput.comp): camera rays
// (coherent) and one cosine-distributed diffuse bounce from each camera hit (incoherent, timed as
// the difference of the two runs). Shared by path_tracer_bench and embree_bench.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <ctime>
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
    // The same per CPU-second of the whole process (lavapipe's worker threads included): on a
    // shared machine less sensitive to the other processes' load than the wall-clock rates.
    double cameraMraysPerCpuSecond = 0.0;
    double bounceMraysPerCpuSecond = 0.0;
    uint64_t cameraRays = 0;
    uint64_t bounceRays = 0;  // camera rays that hit, each followed by one bounce ray
};

// CPU time of the whole process (all threads) in seconds.
inline double processCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

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
    auto timeMode = [&](uint32_t mode, double& cpuSeconds) {
        std::vector<double> times;
        std::vector<double> cpuTimes;
        for (uint32_t r = 0; r < repeat + 1; ++r) {  // the first run warms up (JIT, caches)
            push.mode = mode;
            push.seed = r;
            const auto start = Clock::now();
            const double cpuStart = processCpuSeconds();
            context.submitAndWait([&](VkCommandBuffer cmd) { kernel.record(cmd, rayPixels, push); });
            if (r > 0) {
                times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
                cpuTimes.push_back(processCpuSeconds() - cpuStart);
            }
        }
        cpuSeconds = median(cpuTimes);
        return median(times);
    };
    double cameraCpu = 0.0;
    double bounceCpu = 0.0;
    const double cameraSeconds = timeMode(0, cameraCpu);
    const double bounceSeconds = timeMode(1, bounceCpu);
    RayRates rates;
    rates.cameraRays = rayPixels;
    for (uint32_t h : result.download<uint32_t>()) rates.bounceRays += h >= 1;
    rates.cameraMrays = rayPixels / cameraSeconds / 1e6;
    rates.bounceMrays = rates.bounceRays / std::max(bounceSeconds - cameraSeconds, 1e-9) / 1e6;
    rates.cameraMraysPerCpuSecond = rayPixels / cameraCpu / 1e6;
    rates.bounceMraysPerCpuSecond = rates.bounceRays / std::max(bounceCpu - cameraCpu, 1e-9) / 1e6;
    return rates;
}

}  // namespace vkp::bench
