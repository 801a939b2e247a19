#include "photon/photon_integrator.h"

#include <algorithm>
#include <cmath>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "photon/deposition.h"
#include "photon/photon_map_update.h"
#include "photon/progressive_photon_integrator.h"
#include "shared/kernels/photon_trace.glsl"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace vkp {
namespace {

// The global map's k-nearest estimates search up to this many times the radius that holds k
// photons at the map's mean density (cells are that radius wide: two rings of cells are visited).
constexpr float kGlobalRadiusFactor = 2.0f;
constexpr uint32_t kMaxSpecularDepth = 16;
// The gather guide's grids: 4 x 16 cells (theta bands x phi sectors), sized for this many photons
// per grid (the guided path tracer's defaults, docs/guided-path-tracing.md).
constexpr uint32_t kGatherGuideGridU = 4;
constexpr uint32_t kGatherGuideGridV = 16;
constexpr uint32_t kGatherGuideK = 50;
// The camera passes' stages, timed on the device (vk/stage_timer.h), and their stats keys.
enum CameraStage : uint32_t { kStageVisiblePoints, kStageCaustics, kStageGathers, kStageGatherReuse, kStageCount };
const char* const kCameraStageKeys[kStageCount] = {"timings.photon.visiblePointsSeconds",
                                                   "timings.photon.causticLookupSeconds",
                                                   "timings.photon.gatherSeconds",
                                                   "timings.photon.gatherReuseSeconds"};
// Gathers are shared between pixels (--gather-reuse) with at most this many rays per pixel (the
// reuse kernel's loop visits every ray of up to 17 x 17 pixels) and this much memory for the rays.
constexpr uint32_t kMaxGatherReuseRays = 64;
constexpr uint64_t kMaxGatherSampleBytes = uint64_t(512) << 20;

// The pixels `range` needs around it: `window` rows and pixels before and after, within the frame.
vk::ItemRange withHalo(vk::ItemRange range, uint32_t window, uint32_t width, uint64_t pixels) {
    const uint64_t halo = uint64_t(window) * width + window;
    const uint64_t first = range.first > halo ? range.first - halo : 0;
    const uint64_t end = std::min(pixels, range.first + range.count + halo);
    return {first, end - first};
}

// The pixels of `range` that lie in `window`.
vk::ItemRange within(vk::ItemRange range, vk::ItemRange window) {
    const uint64_t first = std::max(range.first, window.first);
    const uint64_t end = std::min(range.first + range.count, window.first + window.count);
    return {first, end > first ? end - first : 0};
}

}  // namespace

float gatherReuseRadius(float radius, uint32_t sample) {
    return radius * float(std::pow(1.0 + double(sample) / kGatherReuseShrinkSamples, -1.0 / 6.0));
}

gpu::VisiblePointParams visiblePointParams(const Frame& frame, uint32_t lightCount) {
    gpu::VisiblePointParams params{};
    params.camera = frame.gpuCamera;
    params.width = frame.width;
    params.height = frame.height;
    params.seed = frame.seed;
    params.maxSpecularDepth = kMaxSpecularDepth;
    params.lightCount = lightCount;
    params.flags = frame.cameraPathFlags();
    return params;
}

void requireLightPower(const GpuScene& scene) {
    if (!(scene.arrays().totalLightPower > 0.0))
        throw InputError("the scene's lights emit no power: no photons to trace");
}

void reportMapBuild(Stats& stats, const PhotonMapStats& map) {
    stats.add("photons.pathsTraced", map.traced.emitted);
    stats.add("photons.dropped", map.dropped);
    stats.add("photons.seconds", map.traceSeconds + map.gridSeconds);
    stats.add("timings.photon.traceSeconds", map.traceSeconds);
    stats.add("timings.photon.gridSeconds", map.gridSeconds);
}

PhotonIntegrator::PhotonIntegrator(const GpuScene& scene, const PhotonIntegratorSettings& settings)
    : m_scene(scene), m_settings(settings) {
    m_settings.check();
    requireLightPower(scene);
    m_radius = m_settings.radiusFor(scene.scene());
}

// Pass 1: the importons (unless every photon is kept) and the photon maps. The global map's
// search radius follows its density: the radius of a disk holding k photons if they spread
// evenly over the scene's surfaces (with importance deposition, the density where p = 1).
void PhotonIntegrator::buildMaps(const Frame& frame) {
    const PhotonIntegratorSettings& p = m_settings;
    const DepositOptions& deposit = p.deposit;
    vk::Context& context = m_scene.context();
    m_importons = makeImportonMap(m_scene, frame, deposit);
    reportImportons(m_stats, m_importons.get());
    // Keller & Wald's (N, q): N paths for the caustic map, the first q N of them for the global one.
    const bool splitByQ = p.q > 0.0f;
    const uint32_t globalPaths =
        splitByQ ? std::max(1u, uint32_t(std::ceil(double(p.q) * p.globalPaths))) : p.globalPaths;
    const uint32_t causticPaths = splitByQ ? p.globalPaths : p.causticPaths;
    PhotonMapSettings globalSettings;
    globalSettings.paths = globalPaths;
    globalSettings.maxDeposits = p.maxDeposits;
    globalSettings.seed = frame.seed;
    globalSettings.deposit = depositSettings(deposit, deposit.mode, m_importons.get());
    globalSettings.control = &frame.control;
    globalSettings.segmentShift = p.mapSegmentShift;
    const double area = sceneSurfaceArea(m_scene.arrays());
    const uint32_t k = p.gatherK;
    globalSettings.cellSizeFor = [k, area](uint64_t photons) { return evenSpreadRadius(k, photons, area); };
    if (deposit.mode == DepositMode::Density) {
        // Rounds decide against cells of the required density; the stored density is at most
        // the one of all deposits (the even-spread radius of the candidates).
        globalSettings.cellSize = densityCellSize(deposit, k, *m_importons);
        globalSettings.cellSizeFor = [k, area, densityCell = globalSettings.cellSize](uint64_t photons) {
            return std::max(densityCell, evenSpreadRadius(k, photons, area));
        };
    }
    m_globalMap = std::make_unique<PhotonMap>(context, m_scene.scene(), m_scene.arrays(), m_scene.buffers(),
                                              globalSettings);
    const PhotonMapStats globalStats = buildFramePhotonMap(frame, *m_globalMap, 0);
    m_stopReason = globalStats.stopReason;
    m_globalCellSize = globalStats.cellSize;
    reportMapBuild(m_stats, globalStats);
    m_stats.set("photons.globalStored", globalStats.stored);
    m_stats.set("photons.globalTruncated", globalStats.traced.truncated);
    m_stats.set("photons.globalSampled", globalStats.traced.sampled);
    // Paths cut at kPhotonMaxBounces lose the light they would still carry (a path with more
    // deposits than --max-deposits keeps a reweighted sample of them: unbiased, a little noisier).
    if (globalStats.traced.emitted > 0 &&
        double(globalStats.traced.truncated) > 0.01 * double(globalStats.traced.emitted))
        m_stats.note(fmt::format("{:.1f} % of the global map's photon paths were cut at {} bounces; the light they "
                                 "would still carry is lost",
                                 100.0 * double(globalStats.traced.truncated) / double(globalStats.traced.emitted),
                                 gpu::kPhotonMaxBounces));
    m_stats.set("photons.globalDeposits", globalStats.candidates);
    m_stats.add("photons.mapBytes", m_globalMap->bytes());

    m_causticMap.reset();
    if (causticPaths > 0) {
        PhotonMapSettings causticSettings;
        causticSettings.paths = causticPaths;
        causticSettings.maxDeposits = 1;  // a path's first caustic photon (PhotonSettings::requiredFlags)
        causticSettings.seed = frame.seed;
        causticSettings.requiredFlags = gpu::kPhotonCaustic;
        causticSettings.cellSize = 2.0f * m_radius;
        causticSettings.control = &frame.control;
        causticSettings.segmentShift = p.mapSegmentShift;
        // Caustics are seen directly, where density control's path importance does not reach:
        // they are deposited by importance in that mode too.
        causticSettings.deposit = depositSettings(
            deposit, deposit.mode == DepositMode::Density ? DepositMode::Importance : deposit.mode, m_importons.get());
        m_causticMap = std::make_unique<PhotonMap>(context, m_scene.scene(), m_scene.arrays(), m_scene.buffers(),
                                                   causticSettings);
        // Split by q, the global map's paths are the caustic map's first; else fresh Halton indices.
        const PhotonMapStats causticStats = buildFramePhotonMap(frame, *m_causticMap, splitByQ ? 0 : p.globalPaths);
        reportMapBuild(m_stats, causticStats);
        if (m_stopReason.empty()) m_stopReason = causticStats.stopReason;
        m_stats.set("photons.causticStored", causticStats.stored);
        m_stats.set("photons.causticDeposits", causticStats.candidates);
        m_stats.add("photons.mapBytes", m_causticMap->bytes());
    }

    // Final gathers read precomputed radiance photons unless told to estimate at every hit.
    m_radiancePhotons.reset();
    const float globalRadius = kGlobalRadiusFactor * m_globalCellSize;
    // The radiance-photon pass is one dispatch over the map (seconds per million photons on
    // lavapipe) that cannot stop half-way; a render already told to stop skips it, and its final
    // gathers estimate at every hit instead.
    const bool stopped = frame.control.shouldStop();
    if (stopped && p.gatherRays > 0 && p.radiancePhotonStride > 0)
        m_stats.note("stopped before the radiance photons: final gathers estimate at every hit");
    if (p.gatherRays > 0 && p.radiancePhotonStride > 0 && globalStats.stored > 0 && !stopped) {
        const auto start = Clock::now();
        m_radiancePhotons = std::make_unique<RadiancePhotons>(
            context, m_globalMap->grid(), static_cast<uint32_t>(globalStats.stored), m_globalMap->photonPower(),
            p.radiancePhotonStride, p.gatherK, globalRadius);
        context.submitAndWait([&](VkCommandBuffer cmd) { m_radiancePhotons->record(cmd); });
        m_stats.add("photons.seconds", secondsSince(start));
        m_stats.add("timings.photon.radiancePhotonsSeconds", secondsSince(start));
        m_stats.add("photons.mapBytes", m_radiancePhotons->bytes());
    }
    buildGatherGuide(globalStats);
}

// The guiding cache of the final gathers (docs/photon-mapping.md, "Final gathering"): one grid of
// the global map's indirect photons' incoming flux per cache cell and normal bin. Direct photons
// are left out: the gather reads light that arrives after at least one bounce.
void PhotonIntegrator::buildGatherGuide(const PhotonMapStats& globalStats) {
    m_gatherGuide.reset();
    if (m_settings.gatherRays == 0 || m_settings.gatherGuide <= 0.0f || globalStats.stored == 0) return;
    const auto start = Clock::now();
    vk::Context& context = m_scene.context();
    // The indirect share of the stored photons (the deposits' share: the decision keeps each kind alike).
    const PhotonCounters& c = globalStats.traced;
    const double deposits = double(c.storedGlobal + c.storedCaustic + c.storedPrimary);
    const double indirect = deposits > 0.0 ? double(c.storedGlobal + c.storedCaustic) / deposits : 1.0;
    const auto guidePhotons = static_cast<uint64_t>(std::max(1.0, indirect * double(globalStats.stored)));
    gpu::GuideParams params{};
    params.grid.photonPower = m_globalMap->photonPower();
    params.mix = m_settings.gatherGuide;
    params.k = kGatherGuideK;
    params.gridSize = kGatherGuideGridU | (kGatherGuideGridV << 8);
    m_gatherGuide = makeGuideCache(context, m_globalMap->grid().photonArray(), globalStats.stored, guidePhotons, kGatherGuideK,
                                   sceneSurfaceArea(m_scene.arrays()), params, gpu::kPhotonPrimary);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        vk::computeBarrier(cmd);
        m_gatherGuide->record(cmd);
    });
    m_stats.add("photons.mapBytes", m_gatherGuide->bytes());
    m_stats.add("photons.seconds", secondsSince(start));
    m_stats.add("timings.photon.gatherGuideSeconds", secondsSince(start));
}

void PhotonIntegrator::prepare(const Frame& frame, const Film& film) {
    const PhotonIntegratorSettings& p = m_settings;
    vk::Context& context = m_scene.context();
    m_window = frame.pixelRange();
    // A camera change in `vkphoton view` (nothing moved: FrameUpdateInfo::retrace false) keeps
    // maps that do not depend on the camera (--deposit all: no importance decision); only the
    // camera passes below are made again.
    const bool keepMaps = m_globalMap && frame.photonUpdate && !frame.update.retrace && !frame.update.firstFrame &&
                          p.deposit.mode == DepositMode::All && m_stopReason.empty();
    if (!keepMaps) {
        m_stats = Stats();
        buildMaps(frame);
    }
    m_stats.set("photons.mapsKept", keepMaps);  // "photons.pathsTraced" then counts the earlier build
    const float globalRadius = kGlobalRadiusFactor * m_globalCellSize;
    const PhotonGrid& gatherGrid = m_radiancePhotons ? m_radiancePhotons->grid() : m_globalMap->grid();

    // Pass 2's passes: visible points, caustics and final gathers per camera sample.
    m_points = std::make_unique<vk::Buffer>(context, "visible points", frame.pixels() * sizeof(gpu::GpuVisiblePoint),
                                            vk::kStorageUsage);
    m_visiblePass = std::make_unique<VisiblePointPass>(context, m_scene.buffers(), film.sums(), *m_points,
                                                       *frame.rasterDirect);
    // Gathers shared between pixels: every ray of a sample kept until the reuse pass has read it.
    const uint64_t sampleBytes = frame.pixels() * uint64_t(p.gatherRays) * sizeof(gpu::GatherSample);
    const bool reuse = p.gatherRays > 0 && p.gatherReuse > 0.0f && p.gatherRays <= kMaxGatherReuseRays &&
                       sampleBytes <= kMaxGatherSampleBytes;
    if (p.gatherRays > 0 && p.gatherReuse > 0.0f && !reuse)
        m_stats.note(fmt::format("final gathers are not shared between pixels: {} rays per sample at {} x {} need "
                                 "more than {} rays or {} MiB",
                                 p.gatherRays, frame.width, frame.height, kMaxGatherReuseRays, kMaxGatherSampleBytes >> 20));
    m_stats.set("settings.photon.gatherReuseOn", reuse);
    m_gatherSamples.reset();
    m_reusePass.reset();
    if (reuse)
        m_gatherSamples = std::make_unique<vk::Buffer>(context, "final-gather samples", sampleBytes, vk::kStorageUsage);
    m_gatherPass = std::make_unique<FinalGatherPass>(context, m_scene.buffers(), film.sums(), *m_points, gatherGrid,
                                                     m_gatherGuide.get(), m_gatherSamples.get());
    if (reuse)
        m_reusePass = std::make_unique<GatherReusePass>(context, m_scene.buffers(), film.sums(), *m_points, *m_gatherSamples);
    m_causticPass.reset();
    // An empty caustic map (nothing specular the lights reach) has nothing to look up.
    if (m_causticMap && m_causticMap->stored() > 0)
        m_causticPass = std::make_unique<CausticEstimatePass>(context, m_scene.buffers(), film.sums(), *m_points,
                                                              m_causticMap->grid());

    m_timer = std::make_unique<vk::StageTimer>(context, std::vector<std::string>(kCameraStageKeys, kCameraStageKeys + kStageCount),
                                               kStageCount * maxSamplesPerBatch());
    m_visibleParams = visiblePointParams(frame, m_scene.buffers().lightCount());
    m_causticParams = {};
    if (m_causticMap) m_causticParams.grid = m_causticMap->grid().view(m_causticMap->photonPower());
    m_causticParams.width = frame.width;
    m_causticParams.height = frame.height;
    m_causticParams.radius = m_radius;
    m_causticParams.coneK = p.coneK;
    m_gatherParams = {};
    // Radiance photons carry watts per square metre: their power unit is 1.
    m_gatherParams.grid = m_radiancePhotons ? gatherGrid.view(1.0f) : gatherGrid.view(m_globalMap->photonPower());
    m_gatherParams.radianceLookup = m_radiancePhotons ? 1u : 0u;
    m_gatherParams.lookupRadius = m_globalCellSize;  // one ring of cells: several radiance photons
    m_gatherParams.width = frame.width;
    m_gatherParams.height = frame.height;
    m_gatherParams.seed = frame.seed;
    m_gatherParams.gatherRays = p.gatherRays;
    m_gatherParams.k = p.gatherK;
    m_gatherParams.maxRadius = globalRadius;
    m_gatherParams.maxSpecularDepth = kMaxSpecularDepth;
    if (m_gatherGuide) m_gatherParams.guide = m_gatherGuide->params();
    m_gatherParams.reuse = reuse ? 1u : 0u;
    const uint64_t gatherSamples = uint64_t(std::max(frame.gpuCamera.pixelSamples, 1u)) * p.gatherRays;
    m_gatherParams.samplerCount = gatherSamples <= (uint64_t(1) << 30) ? uint32_t(gatherSamples) : 0u;
    m_reuseParams = {};
    m_reuseParams.width = frame.width;
    m_reuseParams.height = frame.height;
    m_reuseParams.gatherRays = p.gatherRays;
    m_reuseParams.footprintScale = std::sqrt(float(std::max(frame.gpuCamera.pixelSamples, 1u)));

    m_stats.set("settings.photon.radius", m_radius);
    m_stats.set("settings.photon.globalRadius", globalRadius);
}

void PhotonIntegrator::recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) {
    m_timer->beginRecording(cmd);
    const uint64_t framePixels = uint64_t(m_reuseParams.width) * m_reuseParams.height;
    for (uint32_t sample = first; sample < first + count; ++sample) {
        // Shared gathers read the rays of pixels up to `window` rows around the window's, so a
        // --tile or --crop part traces those too (their film entries lie outside its image) and
        // gets the values of the full render.
        const vk::ItemRange traced = m_reusePass ? withHalo(m_window, reuseParams(sample).window, m_reuseParams.width, framePixels)
                                                 : m_window;
        recordSample(cmd, sample, traced, m_window, true);
    }
}

void PhotonIntegrator::recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) {
    // Parts go in order through the window; a pixel's shared gathers need the rays of the next
    // `window` rows, so each part shares the gathers of the pixels that far behind its end (the
    // last part, those up to the window's end): every pixel once per sample, after its own visible
    // point and caustics, as recordSamples orders them.
    vk::ItemRange shared = part;
    if (m_reusePass) {
        // The lag in whole granules, so that the shared ranges fall on the parts' SIMD batches too.
        const uint32_t w = reuseParams(sample).window;
        const uint64_t lag = (uint64_t(w) * m_reuseParams.width + w + kSamplePartGranule - 1) / kSamplePartGranule *
                             kSamplePartGranule;
        const uint64_t windowEnd = m_window.first + m_window.count;
        const uint64_t partEnd = part.first + part.count;
        const uint64_t first = std::max(m_window.first, part.first > lag ? part.first - lag : 0);
        const uint64_t end = partEnd >= windowEnd ? windowEnd : std::max(first, partEnd > lag ? partEnd - lag : 0);
        shared = {first, end - first};
    }
    recordSample(cmd, sample, part, shared, false);  // parts are not timed (the stage timer times whole batches)
}

gpu::GatherReuseParams PhotonIntegrator::reuseParams(uint32_t sample) const {
    gpu::GatherReuseParams params = m_reuseParams;
    params.radius = gatherReuseRadius(m_settings.gatherReuse, sample);
    params.window = std::min(uint32_t(std::ceil(params.radius)), gpu::kMaxGatherReuseWindow);
    return params;
}

void PhotonIntegrator::recordSample(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange pixels, vk::ItemRange shared,
                                    bool timed) {
    const auto begin = [&](uint32_t stage) {
        if (timed) m_timer->begin(cmd, stage);
    };
    const auto end = [&](uint32_t stage) {
        if (timed) m_timer->end(cmd, stage);
    };
    m_visibleParams.sampleIndex = sample;
    begin(kStageVisiblePoints);
    m_visiblePass->record(cmd, m_visibleParams, pixels);
    vk::computeBarrier(cmd);
    end(kStageVisiblePoints);
    if (m_causticPass) {
        begin(kStageCaustics);
        m_causticPass->record(cmd, m_causticParams, within(pixels, m_window));  // not the halo
        vk::computeBarrier(cmd);
        end(kStageCaustics);
    }
    // One dispatch per gather ray keeps each invocation's loops within lavapipe's limit.
    m_gatherParams.sampleIndex = sample;
    begin(kStageGathers);
    for (uint32_t ray = 0; ray < std::max(1u, m_settings.gatherRays); ++ray) {
        m_gatherParams.rayIndex = ray;
        m_gatherPass->record(cmd, m_gatherParams, pixels);
        vk::computeBarrier(cmd);
    }
    end(kStageGathers);
    if (m_reusePass && shared.count > 0) {
        begin(kStageGatherReuse);
        m_reusePass->record(cmd, reuseParams(sample), shared);
        vk::computeBarrier(cmd);
        end(kStageGatherReuse);
    }
}

void PhotonIntegrator::report(Stats& stats) const {
    m_settings.report(stats);
    stats.merge(m_stats);
    if (m_timer && m_timer->enabled()) {
        const std::vector<double> seconds = m_timer->seconds();
        for (uint32_t stage = 0; stage < kStageCount; ++stage) stats.set(kCameraStageKeys[stage], seconds[stage]);
    }
    reportPhotonSummary(stats);
}

void reportPhotonSummary(Stats& stats) {
    stats.note(fmt::format("photon maps: {} global and {} caustic photons from {} paths in {:.2f} s ({:.1f} MB); "
                           "radius {:.4g}",
                           stats.getOr<uint64_t>("photons.globalStored", 0),
                           stats.getOr<uint64_t>("photons.causticStored", 0),
                           stats.getOr<uint64_t>("photons.pathsTraced", 0), stats.getOr<double>("photons.seconds", 0.0),
                           stats.getOr<double>("photons.mapBytes", 0.0) / 1048576.0,
                           stats.getOr<double>("settings.photon.radius", 0.0)));
    if (stats.getOr<std::string>("photons.deposit", "all") != "all") {
        const auto share = [](uint64_t kept, uint64_t deposited) { return deposited ? 100.0 * kept / deposited : 0.0; };
        const auto global = stats.getOr<uint64_t>("photons.globalStored", 0);
        const auto globalDeposits = stats.getOr<uint64_t>("photons.globalDeposits", 0);
        const auto caustic = stats.getOr<uint64_t>("photons.causticStored", 0);
        const auto causticDeposits = stats.getOr<uint64_t>("photons.causticDeposits", 0);
        stats.note(fmt::format("deposit {}: kept {} of {} global deposits ({:.1f} %), {} of {} caustic ({:.1f} %); "
                               "{} importons ({:.1f} MB), f = {:.4g}",
                               stats.get<std::string>("photons.deposit"), global, globalDeposits,
                               share(global, globalDeposits), caustic, causticDeposits, share(caustic, causticDeposits),
                               stats.getOr<uint64_t>("photons.importonsStored", 0),
                               stats.getOr<double>("photons.importonBytes", 0.0) / 1048576.0,
                               stats.getOr<double>("photons.importanceScale", 0.0)));
    }
    if (const auto dropped = stats.getOr<uint64_t>("photons.dropped", 0); dropped > 0)
        stats.warn(fmt::format("{} photon(s) did not fit their map: fewer paths or --max-deposits would keep all",
                               dropped));
}

namespace {

// The photon family's one config: photon and sppm read the same photon-map settings.
class PhotonFamilyConfig : public IntegratorConfig {
public:
    void addOptions(IntegratorOptions& options) override { m_settings.addOptions(options); }
    void choose(const std::string& kind) override { m_settings.progressive = kind == "sppm"; }
    void check() const override { m_settings.check(); }
    std::string startMessage(const FrameSettings& frame) const override {
        const PhotonIntegratorSettings& p = m_settings;
        if (p.progressive)
            return fmt::format("tracing {} photon paths ({} per sample) ...",
                               uint64_t(p.globalPaths) * frame.samplesPerPixel, p.globalPaths);
        return fmt::format("tracing {} photon paths ...", uint64_t(p.globalPaths) + p.causticPaths);
    }
    std::unique_ptr<Integrator> create(const GpuScene& scene) const override {
        if (m_settings.progressive) return std::make_unique<ProgressivePhotonIntegrator>(scene, m_settings);
        return std::make_unique<PhotonIntegrator>(scene, m_settings);
    }

private:
    PhotonIntegratorSettings m_settings;
};

}  // namespace

IntegratorKind photonIntegratorKind() {
    return {"photon", "photon mapping: a caustic map and final gathers from the global map, Jensen 1996",
            [] { return std::make_unique<PhotonFamilyConfig>(); }, "photon"};
}

IntegratorKind sppmIntegratorKind() {
    return {"sppm", "stochastic progressive photon mapping, Hachisuka & Jensen 2009 (--progressive)",
            [] { return std::make_unique<PhotonFamilyConfig>(); }, "photon"};
}

}  // namespace vkp
