#include "render/renderer.h"

#include <fmt/format.h>

#include "render/raster_direct.h"
#include "render/sample_loop.h"
#include "render/terminations.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {

Renderer::Renderer(vk::Context& context, const Scene& scene, LightSampling lightSampling)
    : m_scene(context, scene, lightSampling), m_lightSampling(lightSampling) {
    lightSampling.check();
    refreshLightCells();
}

bool Renderer::refreshLightCells() {
    if (m_lightSampling.sampler != LightSampler::Photon) return true;
    if (!m_lightReach) m_lightReach.emplace();
    m_lightCells = prepareLightCells(m_scene, m_lightSampling, &*m_lightReach);
    return m_lightCells->sameBuffer;
}

RenderResult Renderer::render(const FrameSettings& settings, Integrator& integrator, const ProgressCallback& progress,
                              const std::atomic<bool>* stop) {
    settings.check();
    vk::Context& context = m_scene.context();
    const auto start = Clock::now();
    context.memory().resetPeak();  // this render's peak: the scene and what the render allocates

    Frame frame = makeFrame(m_scene.scene(), settings);
    clearTerminations(context);
    frame.control.stop = stop;
    if (settings.timeLimitSeconds > 0.0)
        frame.control.deadline = settings.timeLimitFrom.value_or(start) +
                                 std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(settings.timeLimitSeconds));
    const RasterDirectLight raster(m_scene, settings, frame.gpuCamera, m_lightReach ? &*m_lightReach : nullptr);
    frame.rasterDirect = &raster.direct();
    frame.rasterFlags = raster.pathFlags();

    const Film film(context, settings.width, settings.height);
    context.submitAndWait([&](VkCommandBuffer cmd) { film.recordClear(cmd); });
    integrator.prepare(frame, film);
    const SampleLoopResult loop =
        runSampleLoop(settings.samplesPerPixel, frame.control, integrator.maxSamplesPerBatch(), progress,
                      [&](uint32_t first, uint32_t count) {
                          integrator.beginSamples(first, count);
                          context.submitAndWait([&](VkCommandBuffer cmd) {
                              integrator.recordSamples(cmd, first, count);
                              vk::computeToHostBarrier(cmd);
                          });
                      });
    RenderResult result;
    result.image = film.resolve();
    integrator.finish(result.image, loop.samplesDone);
    if (frame.crop) result.image = cropImage(result.image, *frame.crop);  // --tile, --crop
    const double renderSeconds = secondsSince(start);

    Stats& stats = result.stats;
    const PathTraceCounters counters = film.readCounters();
    stats.set("integrator", integrator.name());
    stats.set("device", context.deviceName());
    stats.set("settings.width", settings.width);
    stats.set("settings.height", settings.height);
    stats.set("settings.spp", settings.samplesPerPixel);
    stats.set("settings.seed", settings.seed);
    stats.set("settings.maxDepth", settings.maxDepth);
    stats.set("settings.timeLimit", settings.timeLimitSeconds);
    stats.set("settings.nextEventEstimation", settings.nextEventEstimation);
    stats.set("settings.areaLightSamples", settings.areaLightSamples);
    raster.report(stats);
    stats.set("scene_stats.triangles", m_scene.arrays().triangles.size());
    stats.set("scene_stats.lights", m_scene.arrays().lights.size());
    stats.set("scene_stats.gpuBytes", m_scene.buffers().bytes());
    const TextureAtlas& atlas = m_scene.arrays().textureAtlas;
    uint64_t texelBytes = 0;
    for (const TextureAtlasEntry& e : atlas.entries) texelBytes += uint64_t(e.width) * e.height * 4;
    stats.set("scene_stats.textures", atlas.entries.size());
    stats.set("scene_stats.textureAtlasBytes", atlas.bytes());      // the array image: layers x width x height x 4
    stats.set("scene_stats.textureTexelBytes", texelBytes);         // the textures' own texels (after downscaling)
    stats.set("scene_stats.textureAtlasLayers", atlas.layers);
    stats.set("scene_stats.texturesDownscaled", atlas.downscaled.size());
    const LightTreeStats& tree = m_scene.arrays().lightTree;
    stats.set("light_sampler.mode", std::string(lightSamplerName(m_scene.arrays().lightSampling.sampler)));
    stats.set("light_sampler.triangleSampling",
              std::string(m_scene.arrays().lightSampling.triangles == TriangleSampling::Area ? "area" : "solid-angle"));
    stats.set("light_sampler.lights", m_scene.arrays().lights.size());
    stats.set("light_sampler.treeLights", tree.treeLights);
    stats.set("light_sampler.infiniteLights", tree.infiniteLights);
    stats.set("light_sampler.treeNodes", tree.nodes);
    stats.set("light_sampler.treeDepth", tree.depth);
    stats.set("light_sampler.bytes", m_scene.arrays().lightCdf.size() * sizeof(float));
    if (m_lightCells) {
        stats.set("light_sampler.cells.photons", m_lightCells->photons);
        stats.set("light_sampler.cells.cells", m_lightCells->cells);
        stats.set("light_sampler.cells.buckets", m_lightCells->buckets);
        stats.set("light_sampler.cells.meanCandidates", m_lightCells->meanCandidates);
        stats.set("light_sampler.cells.bytes", m_lightCells->bytes);
        stats.set("light_sampler.cells.cellSize", double(m_lightCells->cellSize));
        stats.set("light_sampler.cells.seconds", m_lightCells->seconds);
    }
    stats.set("timings.bvhSeconds", m_scene.arrays().bvhBuildSeconds);
    stats.set("timings.uploadSeconds", m_scene.uploadSeconds());
    stats.set("timings.renderSeconds", renderSeconds);
    stats.set("memory.peakBytes", context.memory().peak());  // device memory held at once, at most
    const uint64_t cameraPaths = uint64_t(result.image.width) * result.image.height * loop.samplesDone;
    stats.set("counters.samplesPerPixel", loop.samplesDone);
    stats.set("counters.cameraPaths", cameraPaths);
    stats.set("counters.nonFiniteSamples", counters.nonFiniteSamples);
    stats.set("counters.pathSegments", counters.segments);
    stats.set("counters.pathsPerSecond", renderSeconds > 0.0 ? double(cameraPaths) / renderSeconds : 0.0);
    // A phase before the samples (a photon map, the guide) may have stopped early too.
    const bool preparedFully = !integrator.stoppedEarly();
    stats.set("partial", loop.samplesDone < settings.samplesPerPixel || !preparedFully);
    stats.set("stopReason", loop.stopReason == "complete" && !preparedFully ? integrator.stoppedEarly().value()
                                                                           : loop.stopReason);
    integrator.report(stats);
    reportTerminations(readTerminations(context), stats);
    if (counters.nonFiniteSamples > 0)
        stats.warn(fmt::format("{} sample(s) were NaN or infinite and were dropped", counters.nonFiniteSamples));
    return result;
}

}  // namespace vkp
