#include "render/renderer.h"

#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "passes/guide_cache.h"
#include "passes/path_trace_pass.h"
#include "render/photon_integrator.h"
#include "render/photon_map.h"
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
// Guiding gathers search up to this many times the map's even-spread radius for k photons.
constexpr float kGuideRadiusFactor = 2.0f;

void checkGuideSettings(const GuideRenderSettings& g) {
    if (g.photons == 0) throw InputError("--guide-photons must be at least 1");
    if (g.k == 0 || g.k > gpu::kMaxGatherK)
        throw InputError(fmt::format("--guide-k {}: must be between 1 and {}", g.k, gpu::kMaxGatherK));
    if (g.gridU == 0 || g.gridV == 0 || g.gridU * g.gridV > gpu::kMaxGuideCells || g.gridV > 255)
        throw InputError(fmt::format("--guide-grid {}x{}: needs 1 <= m * n <= {}", g.gridU, g.gridV,
                                     gpu::kMaxGuideCells));
    if (!(g.mix >= 0.0f && g.mix <= 1.0f)) throw InputError(fmt::format("--guide-mix {}: must lie in [0, 1]", g.mix));
}

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
    // The guided path tracer's photon map: direct photons are left out (next-event estimation
    // covers direct light); its grid's cells follow the map's density.
    std::unique_ptr<PhotonMap> guideMap;
    std::unique_ptr<GuideCache> guideCache;
    gpu::GuideParams guide{};
    RenderStats photonStats;
    if (settings.integrator == Integrator::Guided) {
        const GuideRenderSettings& g = settings.guide;
        checkGuideSettings(g);
        PhotonMapSettings mapSettings;
        mapSettings.paths = g.photons;
        mapSettings.seed = settings.seed;
        mapSettings.rejectedFlags = gpu::kPhotonPrimary;
        const double area = sceneSurfaceArea(m_arrays);
        mapSettings.cellSizeFor = [&](uint64_t stored) { return evenSpreadRadius(g.k, stored, area); };
        guideMap = std::make_unique<PhotonMap>(m_context, m_scene, m_arrays, m_buffers, mapSettings);
        const PhotonMapStats mapStats = guideMap->build(0);
        guide.grid = guideMap->grid().view(guideMap->photonPower());
        guide.mix = g.mix;
        guide.k = g.k;
        guide.maxRadius = kGuideRadiusFactor * mapStats.cellSize;
        guide.gridSize = g.gridU | (g.gridV << 8);
        photonStats.photonPathsTraced = mapStats.traced.emitted;
        photonStats.globalPhotons = mapStats.stored;
        photonStats.photonsDropped = mapStats.dropped;
        photonStats.photonSeconds = mapStats.traceSeconds + mapStats.gridSeconds;
        photonStats.photonMapBytes = guideMap->bytes();
        photonStats.globalRadius = guide.maxRadius;
        if (g.cache) {
            // Cache cells twice the even-spread radius: about 4k/pi photons on a flat cell.
            const auto start = Clock::now();
            const float cellSize = 2.0f * mapStats.cellSize;
            const double cells = area / (double(cellSize) * cellSize);
            const uint32_t table = static_cast<uint32_t>(std::clamp(2.0 * cells, 1024.0, double(1u << 20)));
            guideCache = std::make_unique<GuideCache>(m_context, guideMap->grid().photons(), guideMap->capacity(),
                                                      cellSize, table, guide);
            m_context.submitAndWait([&](VkCommandBuffer cmd) {
                vk::computeBarrier(cmd);
                guideCache->record(cmd);
            });
            guide = guideCache->params();
            photonStats.photonSeconds += secondsSince(start);
            photonStats.photonMapBytes += guideCache->bytes();
        }
    }
    const std::string shader = !guideMap ? "pathtrace.comp" : guideCache ? "guided_cached_pathtrace.comp" : "guided_pathtrace.comp";
    std::vector<const vk::Buffer*> guideBuffers;
    if (guideCache) guideBuffers = {&guideCache->cells(), &guideCache->cdfs()};
    else if (guideMap) guideBuffers = {&guideMap->grid().cellStart(), &guideMap->grid().photons()};
    PathTracePass pass(m_context, m_buffers, film, counters, shader, guideBuffers);
    const uint32_t samplesPerDispatch = guideMap ? kMaxGuidedSamplesPerDispatch : kMaxSamplesPerDispatch;

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
    const SampleLoopResult loop = runSampleLoop(settings, 4096, progress, stop, [&](uint32_t first, uint32_t count) {
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            for (uint32_t done = 0; done < count; done += samplesPerDispatch) {
                params.firstSample = first + done;
                params.sampleCount = std::min(samplesPerDispatch, count - done);
                if (guideMap) pass.record(cmd, params, guide);
                else pass.record(cmd, params);
                vk::computeBarrier(cmd);
            }
            vk::computeToHostBarrier(cmd);
        });
    });

    RenderResult result;
    RenderStats& stats = result.stats;
    stats = photonStats;
    stats.integrator = guideMap ? "guided" : "path";
    stats.stopReason = loop.stopReason;
    stats.renderSeconds = loop.seconds + stats.photonSeconds;
    stats.samplesPerPixel = loop.samplesDone;
    stats.partial = loop.samplesDone < settings.samplesPerPixel;
    stats.cameraPaths = pixels * loop.samplesDone;
    stats.nonFiniteSamples = counters.download<uint32_t>()[0];
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
