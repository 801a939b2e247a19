#include "render/renderer.h"

#include <algorithm>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "passes/path_trace_pass.h"
#include "render/photon_integrator.h"
#include "render/raster_direct.h"
#include "render/path_guide.h"
#include "render/sample_loop.h"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace vkp {
namespace {

// Samples per pixel one path-tracing dispatch adds. lavapipe ends every loop of a shader
// invocation once all of them together have run 65535 iterations (docs/photon-mapping.md), and a
// sample costs a few hundred traversal steps: more samples per dispatch would cut paths short.
constexpr uint32_t kMaxSamplesPerDispatch = 8;
// A guided vertex adds a k-nearest gather and the grid's construction to the budget.
constexpr uint32_t kMaxGuidedSamplesPerDispatch = 2;
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
    RenderResult result;
    if (settings.integrator == Integrator::Photon) {
        PhotonIntegrator integrator(m_context, m_scene, m_arrays, m_buffers);
        result = integrator.render(settings, progress, stop);
    } else {
        result = renderPath(settings, progress, stop);
    }
    fillSceneStats(result.stats);
    return result;
}

RenderResult Renderer::renderPath(const RenderSettings& settings, const ProgressCallback& progress,
                                  const std::atomic<bool>* stop) {
    const uint64_t pixels = uint64_t(settings.width) * settings.height;
    vk::Buffer film(m_context, "film", pixels * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Buffer counters(m_context, "counters", 16 * sizeof(uint32_t), vk::kStorageUsage);
    const gpu::GpuCamera camera = makeGpuCamera(chooseCamera(m_scene, settings.cameraIndex), settings.width, settings.height);
    RenderResult result;
    RenderStats& stats = result.stats;

    const RasterDirectLight raster(m_context, m_scene, m_arrays, m_buffers, settings);
    raster.addStats(stats);
    const vk::Buffer& rasterDirect = raster.direct();

    std::unique_ptr<PathGuide> guide;
    if (settings.integrator == Integrator::Guided)
        guide = std::make_unique<PathGuide>(m_context, m_scene, m_arrays, m_buffers, settings.guide, settings.seed);
    const PathTracePass pass = guide ? PathTracePass(m_context, m_buffers, film, counters, rasterDirect, guide->shader(),
                                                     guide->buffers())
                                     : PathTracePass(m_context, m_buffers, film, counters, rasterDirect);
    const uint32_t samplesPerDispatch = guide ? kMaxGuidedSamplesPerDispatch : kMaxSamplesPerDispatch;

    gpu::PathTraceParams params{};
    params.camera = camera;
    params.width = settings.width;
    params.height = settings.height;
    params.seed = settings.seed;
    params.maxDepth = settings.maxDepth;
    params.lightCount = m_buffers.lightCount();
    params.flags = (settings.nextEventEstimation ? 0u : gpu::kPathFlagNoDirectLightSampling) | raster.pathFlags() |
                   (settings.pixelCentres ? gpu::kPathFlagPixelCentres : 0u) |
                   (guide && settings.guide.roulette ? gpu::kPathFlagGuideRoulette : 0u);

    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        film.fillZero(cmd);
        counters.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
    });
    const SampleLoopResult loop = runSampleLoop(settings, 4096, progress, stop, [&](uint32_t first, uint32_t count) {
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            for (uint32_t done = 0; done < count; done += samplesPerDispatch) {
                params.firstSample = first + done;
                params.sampleCount = std::min(samplesPerDispatch, count - done);
                if (guide) pass.record(cmd, params, guide->params());
                else pass.record(cmd, params);
                vk::computeBarrier(cmd);
            }
            vk::computeToHostBarrier(cmd);
        });
    });

    if (guide) guide->addStats(stats);
    stats.integrator = guide ? "guided" : "path";
    stats.stopReason = loop.stopReason;
    stats.renderSeconds = loop.seconds + stats.photonSeconds + stats.rasterSeconds;
    stats.samplesPerPixel = loop.samplesDone;
    stats.partial = loop.samplesDone < settings.samplesPerPixel;
    stats.cameraPaths = pixels * loop.samplesDone;
    const std::vector<uint32_t> counts = counters.download<uint32_t>();
    stats.nonFiniteSamples = counts[0];
    stats.pathSegments = counts[1] | (uint64_t(counts[2]) << 32);
    result.image = resolveFilm(film.download<glm::vec4>(), settings.width, settings.height);
    return result;
}

void Renderer::fillSceneStats(RenderStats& stats) const {
    stats.device = m_context.deviceName();
    stats.triangles = m_arrays.triangles.size();
    stats.lights = m_arrays.lights.size();
    stats.gpuSceneBytes = m_buffers.bytes();
    stats.bvhSeconds = m_arrays.bvhBuildSeconds;
    stats.uploadSeconds = m_uploadSeconds;
}

}  // namespace vkp
