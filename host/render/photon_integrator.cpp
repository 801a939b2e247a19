#include "render/photon_integrator.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "passes/radiance_photons.h"
#include "passes/scene_pass.h"
#include "passes/visible_point_pass.h"
#include "render/raster_direct.h"
#include "render/deposition.h"
#include "render/photon_map.h"
#include "render/sample_loop.h"
#include "shared/photon_render.glsl"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace vkp {
namespace {

// The global map's k-nearest estimates search up to this many times the radius that holds k
// photons at the map's mean density (cells are that radius wide: two rings of cells are visited).
constexpr float kGlobalRadiusFactor = 2.0f;
constexpr uint32_t kMaxSpecularDepth = 16;

void checkSettings(const PhotonRenderSettings& p, float radius) {
    if (p.globalPaths == 0) throw InputError("--photons must be at least 1");
    if (p.gatherK == 0 || p.gatherK > gpu::kMaxGatherK)
        throw InputError(fmt::format("--gather-k {}: must be between 1 and {}", p.gatherK, gpu::kMaxGatherK));
    if (!(radius > 0.0f) || !std::isfinite(radius))
        throw InputError(fmt::format("--radius {}: must be a positive length", radius));
    if (!(p.coneK >= 1.0f)) throw InputError(fmt::format("cone filter k {}: must be at least 1", p.coneK));
    if (!(p.alpha > 0.0f && p.alpha < 1.0f)) throw InputError(fmt::format("alpha {}: must lie in (0, 1)", p.alpha));
    if (!(p.q >= 0.0f && p.q <= 1.0f)) throw InputError(fmt::format("--q {}: must lie in (0, 1]", p.q));
}

gpu::VisiblePointParams visiblePointParams(const RenderSettings& s, const Scene& scene, uint32_t lightCount,
                                           const RasterDirectLight& raster) {
    gpu::VisiblePointParams params{};
    params.camera = makeGpuCamera(chooseCamera(scene, s.cameraIndex), s.width, s.height);
    params.width = s.width;
    params.height = s.height;
    params.seed = s.seed;
    params.maxSpecularDepth = kMaxSpecularDepth;
    params.lightCount = lightCount;
    params.flags = raster.pathFlags() | (s.pixelCentres ? gpu::kPathFlagPixelCentres : 0u);
    return params;
}

void addMapStats(RenderStats& stats, const PhotonMapStats& map) {
    stats.photonPathsTraced += map.traced.emitted;
    stats.photonsDropped += map.dropped;
    stats.photonSeconds += map.traceSeconds + map.gridSeconds;
}

}  // namespace

PhotonIntegrator::PhotonIntegrator(vk::Context& context, const Scene& scene, const SceneArrays& arrays,
                                   const SceneBuffers& buffers)
    : m_context(context), m_scene(scene), m_arrays(arrays), m_buffers(buffers) {
    if (!(arrays.totalLightPower > 0.0)) throw InputError("the scene's lights emit no power: no photons to trace");
}

float PhotonIntegrator::defaultRadius(const Scene& scene) {
    return 0.015f * std::max(0.5f * glm::length(scene.bounds.extent()), 1e-6f);
}

RenderResult PhotonIntegrator::render(const RenderSettings& settings, const ProgressCallback& progress,
                                      const std::atomic<bool>* stop) {
    const float radius = settings.photon.radius > 0.0f ? settings.photon.radius : defaultRadius(m_scene);
    checkSettings(settings.photon, radius);
    RenderResult result = settings.photon.progressive ? renderProgressive(settings, radius, progress, stop)
                                                      : renderTwoPass(settings, radius, progress, stop);
    RenderStats& stats = result.stats;
    stats.deposit = depositModeName(settings.photon.deposit);
    stats.integrator = settings.photon.progressive ? "photon (progressive)" : "photon";
    stats.gatherRadius = radius;
    stats.partial = stats.samplesPerPixel < settings.samplesPerPixel;
    stats.cameraPaths = uint64_t(settings.width) * settings.height * stats.samplesPerPixel;
    return result;
}

RenderResult PhotonIntegrator::renderTwoPass(const RenderSettings& settings, float radius,
                                             const ProgressCallback& progress, const std::atomic<bool>* stop) {
    const PhotonRenderSettings& p = settings.photon;
    RenderResult result;
    RenderStats& stats = result.stats;

    // Pass 1: the importons (unless every photon is kept) and the photon maps. The global map's
    // search radius follows its density: the radius of a disk holding k photons if they spread
    // evenly over the scene's surfaces (with importance deposition, the density where p = 1).
    const std::unique_ptr<ImportonMap> importons = makeImportonMap(m_context, m_scene, m_arrays, m_buffers, settings);
    addImportonStats(stats, importons.get());
    // Keller & Wald's (N, q): N paths for the caustic map, the first q N of them for the global one.
    const bool splitByQ = p.q > 0.0f;
    const uint32_t globalPaths = splitByQ ? std::max(1u, uint32_t(std::ceil(double(p.q) * p.globalPaths))) : p.globalPaths;
    const uint32_t causticPaths = splitByQ ? p.globalPaths : p.causticPaths;
    PhotonMapSettings globalSettings;
    globalSettings.paths = globalPaths;
    globalSettings.maxDeposits = p.maxDeposits;
    globalSettings.seed = settings.seed;
    globalSettings.deposit = depositSettings(p, p.deposit, importons.get());
    const double area = sceneSurfaceArea(m_arrays);
    globalSettings.cellSizeFor = [&](uint64_t photons) { return evenSpreadRadius(p.gatherK, photons, area); };
    if (p.deposit == DepositMode::Density) {
        // Rounds decide against cells of the required density; the stored density is at most
        // the one of all deposits (the even-spread radius of the candidates).
        globalSettings.cellSize = densityCellSize(p, p.gatherK, *importons);
        globalSettings.cellSizeFor = [&, densityCell = globalSettings.cellSize](uint64_t photons) {
            return std::max(densityCell, evenSpreadRadius(p.gatherK, photons, area));
        };
    }
    PhotonMap globalMap(m_context, m_scene, m_arrays, m_buffers, globalSettings);
    const PhotonMapStats globalStats = globalMap.build(0);
    const float globalRadius = kGlobalRadiusFactor * globalStats.cellSize;
    stats.globalRadius = globalRadius;
    addMapStats(stats, globalStats);
    stats.globalPhotons = globalStats.stored;
    stats.globalCandidates = globalStats.candidates;
    stats.photonMapBytes += globalMap.bytes();

    std::unique_ptr<PhotonMap> causticMap;
    if (causticPaths > 0) {
        PhotonMapSettings causticSettings;
        causticSettings.paths = causticPaths;
        causticSettings.maxDeposits = 1;  // a caustic photon is its path's first deposit
        causticSettings.seed = settings.seed;
        causticSettings.requiredFlags = gpu::kPhotonCaustic;
        causticSettings.cellSize = 2.0f * radius;
        // Caustics are seen directly, where density control's path importance does not reach:
        // they are deposited by importance in that mode too.
        causticSettings.deposit = depositSettings(
            p, p.deposit == DepositMode::Density ? DepositMode::Importance : p.deposit, importons.get());
        causticMap = std::make_unique<PhotonMap>(m_context, m_scene, m_arrays, m_buffers, causticSettings);
        // Split by q, the global map's paths are the caustic map's first; else fresh Halton indices.
        const PhotonMapStats causticStats = causticMap->build(splitByQ ? 0 : p.globalPaths);
        addMapStats(stats, causticStats);
        stats.causticPhotons = causticStats.stored;
        stats.causticCandidates = causticStats.candidates;
        stats.photonMapBytes += causticMap->bytes();
    }

    // Final gathers read precomputed radiance photons unless told to estimate at every hit.
    std::unique_ptr<RadiancePhotons> radiancePhotons;
    if (p.gatherRays > 0 && p.radiancePhotonStride > 0 && globalStats.stored > 0) {
        const auto start = Clock::now();
        radiancePhotons = std::make_unique<RadiancePhotons>(m_context, globalMap.grid(),
                                                            static_cast<uint32_t>(globalStats.stored),
                                                            globalMap.photonPower(), p.radiancePhotonStride,
                                                            p.gatherK, globalRadius);
        m_context.submitAndWait([&](VkCommandBuffer cmd) { radiancePhotons->record(cmd); });
        stats.photonSeconds += secondsSince(start);
        stats.photonMapBytes += radiancePhotons->bytes();
    }
    const PhotonGrid& gatherGrid = radiancePhotons ? radiancePhotons->grid() : globalMap.grid();

    // Pass 2: visible points, caustics and final gathers per camera sample.
    const uint64_t pixels = uint64_t(settings.width) * settings.height;
    vk::Buffer film(m_context, "film", pixels * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Buffer points(m_context, "visible points", pixels * sizeof(gpu::GpuVisiblePoint), vk::kStorageUsage);
    const RasterDirectLight raster(m_context, m_scene, m_arrays, m_buffers, settings);
    raster.addStats(stats);
    VisiblePointPass visiblePass(m_context, m_buffers, film, points, raster.direct());
    ScenePass gatherPass(m_context, "final_gather.comp", m_buffers,
                         {&film, &points, &gatherGrid.cellStart(), &gatherGrid.photons()},
                         sizeof(gpu::FinalGatherParams));
    std::unique_ptr<ScenePass> causticPass;
    if (causticMap)
        causticPass = std::make_unique<ScenePass>(
            m_context, "caustic_estimate.comp", m_buffers,
            std::vector<const vk::Buffer*>{&film, &points, &causticMap->grid().cellStart(), &causticMap->grid().photons()},
            sizeof(gpu::CausticEstimateParams));

    gpu::VisiblePointParams vpParams = visiblePointParams(settings, m_scene, m_buffers.lightCount(), raster);
    gpu::CausticEstimateParams causticParams{};
    if (causticMap) causticParams.grid = causticMap->grid().view(causticMap->photonPower());
    causticParams.width = settings.width;
    causticParams.height = settings.height;
    causticParams.radius = radius;
    causticParams.coneK = p.coneK;
    gpu::FinalGatherParams gatherParams{};
    // Radiance photons carry watts per square metre: their power unit is 1.
    gatherParams.grid = radiancePhotons ? gatherGrid.view(1.0f) : gatherGrid.view(globalMap.photonPower());
    gatherParams.radianceLookup = radiancePhotons ? 1u : 0u;
    gatherParams.lookupRadius = globalStats.cellSize;  // one ring of cells: several radiance photons
    gatherParams.width = settings.width;
    gatherParams.height = settings.height;
    gatherParams.seed = settings.seed;
    gatherParams.gatherRays = p.gatherRays;
    gatherParams.k = p.gatherK;
    gatherParams.maxRadius = globalRadius;
    gatherParams.maxSpecularDepth = kMaxSpecularDepth;

    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        film.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
    });
    const SampleLoopResult loop = runSampleLoop(settings, 64, progress, stop, [&](uint32_t first, uint32_t count) {
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            for (uint32_t sample = first; sample < first + count; ++sample) {
                vpParams.sampleIndex = sample;
                visiblePass.record(cmd, vpParams);
                vk::computeBarrier(cmd);
                if (causticPass) {
                    causticPass->record(cmd, pixels, causticParams);
                    vk::computeBarrier(cmd);
                }
                // One dispatch per gather ray keeps each invocation's loops within lavapipe's limit.
                gatherParams.sampleIndex = sample;
                for (uint32_t ray = 0; ray < std::max(1u, p.gatherRays); ++ray) {
                    gatherParams.rayIndex = ray;
                    gatherPass.record(cmd, pixels, gatherParams);
                    vk::computeBarrier(cmd);
                }
            }
            vk::computeToHostBarrier(cmd);
        });
    });
    stats.stopReason = loop.stopReason;
    stats.renderSeconds = loop.seconds + stats.photonSeconds + stats.rasterSeconds;
    stats.samplesPerPixel = loop.samplesDone;
    result.image = resolveFilm(film.download<glm::vec4>(), settings.width, settings.height);
    return result;
}

RenderResult PhotonIntegrator::renderProgressive(const RenderSettings& settings, float radius,
                                                 const ProgressCallback& progress, const std::atomic<bool>* stop) {
    const PhotonRenderSettings& p = settings.photon;
    RenderResult result;
    RenderStats& stats = result.stats;
    const uint64_t pixels = uint64_t(settings.width) * settings.height;

    // One map of every non-direct photon (caustic and global alike), rebuilt each pass; radii only
    // shrink, so cells of twice the initial radius serve every pass.
    PhotonMapSettings mapSettings;
    mapSettings.paths = p.globalPaths;
    mapSettings.maxDeposits = p.maxDeposits;
    mapSettings.seed = settings.seed;
    mapSettings.rejectedFlags = gpu::kPhotonPrimary;
    mapSettings.cellSize = 2.0f * radius;
    const std::unique_ptr<ImportonMap> importons = makeImportonMap(m_context, m_scene, m_arrays, m_buffers, settings);
    addImportonStats(stats, importons.get());
    mapSettings.deposit = depositSettings(p, p.deposit, importons.get());
    PhotonMap map(m_context, m_scene, m_arrays, m_buffers, mapSettings);

    vk::Buffer film(m_context, "film", pixels * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Buffer points(m_context, "visible points", pixels * sizeof(gpu::GpuVisiblePoint), vk::kStorageUsage);
    std::vector<gpu::SppmPixel> initial(pixels);
    for (auto& px : initial) px.radius2 = radius * radius;
    vk::Buffer sppm = vk::makeStorageBuffer(m_context, "sppm pixels", initial);
    const RasterDirectLight raster(m_context, m_scene, m_arrays, m_buffers, settings);
    raster.addStats(stats);
    VisiblePointPass visiblePass(m_context, m_buffers, film, points, raster.direct());
    ScenePass updatePass(m_context, "sppm_update.comp", m_buffers,
                         {&sppm, &points, &map.grid().cellStart(), &map.grid().photons()}, sizeof(gpu::SppmParams));
    gpu::VisiblePointParams vpParams = visiblePointParams(settings, m_scene, m_buffers.lightCount(), raster);
    gpu::SppmParams sppmParams{};
    sppmParams.grid = map.grid().view(map.photonPower());
    sppmParams.width = settings.width;
    sppmParams.height = settings.height;
    sppmParams.alpha = p.alpha;

    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        film.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
    });
    const SampleLoopResult loop = runSampleLoop(settings, 1, progress, stop, [&](uint32_t pass, uint32_t) {
        const PhotonMapStats mapStats = map.build(pass * p.globalPaths);
        addMapStats(stats, mapStats);
        stats.globalPhotons = mapStats.stored;
        stats.globalCandidates = mapStats.candidates;
        vpParams.sampleIndex = pass;
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            vk::computeBarrier(cmd);
            visiblePass.record(cmd, vpParams);
            vk::computeBarrier(cmd);
            updatePass.record(cmd, pixels, sppmParams);
            vk::computeToHostBarrier(cmd);
        });
    });
    stats.stopReason = loop.stopReason;
    stats.renderSeconds = loop.seconds + stats.rasterSeconds;
    stats.photonMapBytes += map.bytes();
    stats.samplesPerPixel = loop.samplesDone;

    // Direct light (the film's mean) plus tau / (P pi R^2).
    result.image = resolveFilm(film.download<glm::vec4>(), settings.width, settings.height);
    const auto state = sppm.download<gpu::SppmPixel>();
    const float passes = static_cast<float>(std::max(1u, loop.samplesDone));
    for (uint64_t i = 0; i < pixels; ++i) {
        const gpu::SppmPixel& px = state[i];
        const glm::vec3 l = px.flux / (passes * gpu::kPi * px.radius2);
        for (int c = 0; c < 3; ++c) result.image.pixels[3 * i + c] += std::isfinite(l[c]) ? l[c] : 0.0f;
    }
    return result;
}

}  // namespace vkp
