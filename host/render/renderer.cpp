#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "passes/path_trace_pass.h"
#include "util/errors.h"
#include "vk/context.h"

namespace vkp {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Each submission aims at this much device time, so progress, the time limit and Ctrl-C are
// honoured promptly while few submissions keep the per-dispatch overhead small.
constexpr double kTargetBatchSeconds = 0.3;

}  // namespace

Camera chooseCamera(const Scene& scene, int index) {
    if (index >= 0) {
        if (static_cast<size_t>(index) >= scene.cameras.size())
            throw InputError(fmt::format("--camera {}: the scene has {} camera(s)", index, scene.cameras.size()));
        return scene.cameras[index];
    }
    if (!scene.cameras.empty()) return scene.cameras.front();
    return defaultCamera(scene.bounds);
}

Renderer::Renderer(vk::Context& context, const Scene& scene)
    : m_context(context), m_scene(scene), m_arrays(buildSceneArrays(scene)),
      m_buffers([&] {
          const auto start = Clock::now();
          SceneBuffers buffers(context, m_arrays);
          m_uploadSeconds = secondsSince(start);
          return buffers;
      }()) {}

RenderResult Renderer::render(const RenderSettings& settings, const ProgressCallback& progress,
                              const std::atomic<bool>* stop) {
    if (settings.width == 0 || settings.height == 0)
        throw InputError("the image must be at least 1x1 pixels");
    const uint64_t pixels = uint64_t(settings.width) * settings.height;
    vk::Buffer film(m_context, "film", pixels * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Buffer counters(m_context, "counters", 16 * sizeof(uint32_t), vk::kStorageUsage);
    PathTracePass pass(m_context, m_buffers, film, counters);

    gpu::PathTraceParams params{};
    params.camera = makeGpuCamera(chooseCamera(m_scene, settings.cameraIndex), settings.width, settings.height);
    params.width = settings.width;
    params.height = settings.height;
    params.seed = settings.seed;
    params.maxDepth = settings.maxDepth;
    params.lightCount = m_buffers.lightCount();
    params.flags = settings.nextEventEstimation ? 0u : gpu::kPathFlagNoDirectLightSampling;

    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        film.fillZero(cmd);
        counters.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
    });

    RenderResult result;
    RenderStats& stats = result.stats;
    stats.stopReason = "complete";
    const auto start = Clock::now();
    uint32_t done = 0;
    uint32_t batch = 1;
    while (done < settings.samplesPerPixel) {
        if (stop && stop->load()) { stats.stopReason = "interrupted"; break; }
        if (settings.timeLimitSeconds > 0.0 && secondsSince(start) >= settings.timeLimitSeconds) {
            stats.stopReason = "time limit";
            break;
        }
        params.firstSample = done;
        params.sampleCount = std::min(batch, settings.samplesPerPixel - done);
        const auto batchStart = Clock::now();
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            pass.record(cmd, params);
            vk::computeBarrier(cmd);
            vk::computeToHostBarrier(cmd);
        });
        const double batchSeconds = secondsSince(batchStart);
        done += params.sampleCount;
        // Grow or shrink the next batch towards the target time per submission.
        const double perSample = batchSeconds / params.sampleCount;
        double next = perSample > 0.0 ? kTargetBatchSeconds / perSample : 2.0 * batch;
        if (settings.timeLimitSeconds > 0.0)
            next = std::min(next, std::max(1.0, (settings.timeLimitSeconds - secondsSince(start)) / perSample));
        batch = static_cast<uint32_t>(std::clamp(next, 1.0, 4096.0));
        if (progress) progress({done, settings.samplesPerPixel, secondsSince(start)});
    }
    stats.renderSeconds = secondsSince(start);
    stats.samplesPerPixel = done;
    stats.partial = done < settings.samplesPerPixel;
    stats.cameraPaths = pixels * done;
    stats.device = m_context.deviceName();
    stats.triangles = m_arrays.triangles.size();
    stats.lights = m_arrays.lights.size();
    stats.gpuSceneBytes = m_buffers.bytes();
    stats.bvhSeconds = m_arrays.bvhBuildSeconds;
    stats.uploadSeconds = m_uploadSeconds;

    const auto sums = film.download<glm::vec4>();
    stats.nonFiniteSamples = counters.download<uint32_t>()[0];
    result.image.width = settings.width;
    result.image.height = settings.height;
    result.image.pixels.resize(pixels * 3);
    for (uint64_t i = 0; i < pixels; ++i) {
        const glm::vec4 s = sums[i];
        const float inv = s.w > 0.0f ? 1.0f / s.w : 0.0f;
        result.image.pixels[3 * i + 0] = s.x * inv;
        result.image.pixels[3 * i + 1] = s.y * inv;
        result.image.pixels[3 * i + 2] = s.z * inv;
    }
    return result;
}

}  // namespace vkp
