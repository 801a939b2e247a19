#include "app/commands.h"

#include <array>
#include <chrono>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/interrupt.h"
#include "app/progress.h"
#include "image/atomic_file.h"
#include "image/exr.h"
#include "image/metrics.h"
#include "render/photon_export.h"
#include "render/guide_debug.h"
#include "render/deposition.h"
#include "render/photon_map.h"
#include "image/png.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"
#include "vk/context.h"

namespace vkp {
namespace {

using Clock = std::chrono::steady_clock;

std::filesystem::path defaultOutput(const std::filesystem::path& scene) {
    return std::filesystem::path("out") / (scene.stem().string() + ".exr");
}

nlohmann::json statsToJson(const RenderCommandOptions& options, const RenderStats& stats, const ImageRgb& image,
                           double loadSeconds, double totalSeconds) {
    const RenderSettings& s = options.settings;
    nlohmann::json j;
    j["scene"] = options.scene.string();
    j["integrator"] = stats.integrator;
    j["settings"] = {{"width", s.width}, {"height", s.height}, {"spp", s.samplesPerPixel},
                     {"seed", s.seed}, {"maxDepth", s.maxDepth}, {"timeLimit", s.timeLimitSeconds},
                     {"nextEventEstimation", s.nextEventEstimation}, {"direct", stats.direct},
                     {"areaLightSamples", s.areaLightSamples}};
    if (s.direct == DirectLight::Raster)
        j["raster"] = {{"lights", stats.rasterLights}, {"seconds", stats.rasterSeconds}};
    if (s.integrator == Integrator::Photon) {
        const PhotonRenderSettings& p = s.photon;
        j["settings"]["photon"] = {{"photons", p.globalPaths}, {"causticPhotons", p.causticPaths},
                                   {"gatherRays", p.gatherRays}, {"gatherK", p.gatherK},
                                   {"radiancePhotons", p.radiancePhotonStride},
                                   {"radius", stats.gatherRadius}, {"globalRadius", stats.globalRadius}, {"progressive", p.progressive},
                                   {"alpha", p.alpha}, {"deposit", stats.deposit}, {"q", p.q},
                                   {"importons", p.importonPaths}, {"depositEpsilon", p.depositEpsilon},
                                   {"depositCutoff", p.depositCutoff}, {"densityAccuracy", p.densityAccuracy},
                                   {"densityRounds", p.densityRounds}, {"densityRoulette", p.densityRoulette}};
    }
    if (s.integrator == Integrator::Guided) {
        const GuideRenderSettings& g = s.guide;
        j["settings"]["guide"] = {{"photons", g.photons}, {"k", g.k}, {"grid", fmt::format("{}x{}", g.gridU, g.gridV)},
                                  {"mix", g.mix}, {"cache", g.cache}, {"roulette", g.roulette}, {"adapt", g.adaptPhotons},
                                  {"searchRadius", stats.globalRadius}};
    }
    if (s.integrator != Integrator::Path) {
        j["photons"] = {{"pathsTraced", stats.photonPathsTraced}, {"globalStored", stats.globalPhotons},
                        {"causticStored", stats.causticPhotons}, {"dropped", stats.photonsDropped},
                        {"mapBytes", stats.photonMapBytes}, {"seconds", stats.photonSeconds},
                        {"deposit", stats.deposit}, {"globalDeposits", stats.globalCandidates},
                        {"causticDeposits", stats.causticCandidates}, {"importonsStored", stats.importons}, {"importonBytes", stats.importonBytes},
                        {"importanceScale", stats.importanceScale}};
    }
    j["device"] = stats.device;
    j["scene_stats"] = {{"triangles", stats.triangles}, {"lights", stats.lights},
                        {"gpuBytes", stats.gpuSceneBytes}};
    j["timings"] = {{"loadSeconds", loadSeconds}, {"bvhSeconds", stats.bvhSeconds},
                    {"uploadSeconds", stats.uploadSeconds}, {"renderSeconds", stats.renderSeconds},
                    {"totalSeconds", totalSeconds}};
    j["counters"] = {{"samplesPerPixel", stats.samplesPerPixel}, {"cameraPaths", stats.cameraPaths},
                     {"nonFiniteSamples", stats.nonFiniteSamples}, {"pathSegments", stats.pathSegments},
                     {"pathsPerSecond", stats.renderSeconds > 0 ? stats.cameraPaths / stats.renderSeconds : 0.0}};
    j["meanRadiance"] = meanRadiance(image);
    j["partial"] = stats.partial;
    j["stopReason"] = stats.stopReason;
    return j;
}

void printDepositStats(const RenderStats& stats) {
    const auto share = [](uint64_t kept, uint64_t deposited) { return deposited ? 100.0 * kept / deposited : 0.0; };
    fmt::print(stderr, "deposit {}: kept {} of {} global deposits ({:.1f} %), {} of {} caustic ({:.1f} %); "
                       "{} importons ({:.1f} MB), f = {:.4g}\n",
               stats.deposit, stats.globalPhotons, stats.globalCandidates, share(stats.globalPhotons, stats.globalCandidates),
               stats.causticPhotons, stats.causticCandidates, share(stats.causticPhotons, stats.causticCandidates),
               stats.importons, stats.importonBytes / 1048576.0, stats.importanceScale);
}

}  // namespace

int runRender(const RenderCommandOptions& options) {
    const auto start = Clock::now();
    const std::filesystem::path exrPath = options.output.empty() ? defaultOutput(options.scene) : options.output;
    if (exrPath.extension() != ".exr")
        throw InputError(fmt::format("-o {}: the output must end in .exr (a .png is written beside it)", exrPath.string()));
    std::filesystem::path pngPath = exrPath;
    pngPath.replace_extension(".png");

    const Scene scene = loadGltf(options.scene);
    const double loadSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (scene.droppedDegenerateTriangles > 0)
        fmt::print(stderr, "warning: {}: dropped {} degenerate triangle(s)\n", options.scene.string(),
                   scene.droppedDegenerateTriangles);
    // Validate the camera choice before the expensive set-up.
    chooseCamera(scene, options.settings.cameraIndex);

    vk::Context context({options.validate, options.device});
    if (!options.quiet)
        fmt::print(stderr, "vkphoton: {} ({} triangles) on {}{}\n", options.scene.string(),
                   scene.triangles.size(), context.deviceName(), context.validationEnabled() ? " with validation" : "");
    installInterruptHandler();
    Renderer renderer(context, scene);
    const RenderSettings& rs = options.settings;
    if (!options.quiet && rs.integrator == Integrator::Photon)
        fmt::print(stderr, "tracing {} photon paths{} ...\n",
                   rs.photon.progressive ? uint64_t(rs.photon.globalPaths) * rs.samplesPerPixel
                                         : uint64_t(rs.photon.globalPaths) + rs.photon.causticPaths,
                   rs.photon.progressive ? fmt::format(" ({} per sample)", rs.photon.globalPaths) : "");
    if (!options.quiet && rs.integrator == Integrator::Guided)
        fmt::print(stderr, "tracing {} guiding photon paths ...\n", rs.guide.photons);
    ProgressReporter progress("render", options.quiet);
    RenderResult result = renderer.render(
        options.settings,
        [&](const RenderProgress& p) { progress.update(p.samplesDone, p.samplesTotal, p.elapsedSeconds); },
        &interruptRequested());
    progress.finish();
    const RenderStats& stats = result.stats;
    const double totalSeconds = std::chrono::duration<double>(Clock::now() - start).count();

    const RenderSettings& s = options.settings;
    std::vector<std::pair<std::string, std::string>> attributes{
        {"vkphoton/scene", options.scene.string()},
        {"vkphoton/integrator", stats.integrator},
        {"vkphoton/spp", std::to_string(stats.samplesPerPixel)},
        {"vkphoton/sppRequested", std::to_string(s.samplesPerPixel)},
        {"vkphoton/seed", std::to_string(s.seed)},
        {"vkphoton/maxDepth", std::to_string(s.maxDepth)},
        {"vkphoton/device", stats.device},
        {"vkphoton/renderSeconds", fmt::format("{:.3f}", stats.renderSeconds)},
        {"vkphoton/totalSeconds", fmt::format("{:.3f}", totalSeconds)},
        {"vkphoton/partial", stats.partial ? "true" : "false"},
        {"vkphoton/stopReason", stats.stopReason},
    };
    writeExr(exrPath, result.image, attributes);
    writePng(pngPath, result.image);
    if (!options.statsJson.empty())
        writeTextAtomically(options.statsJson, statsToJson(options, stats, result.image, loadSeconds, totalSeconds).dump(2) + "\n");
    if (stats.photonsDropped > 0)
        fmt::print(stderr, "warning: {} photon(s) did not fit their map: fewer paths or --max-deposits would keep all\n",
                   stats.photonsDropped);
    if (stats.nonFiniteSamples > 0)
        fmt::print(stderr, "warning: {} sample(s) were NaN or infinite and were dropped\n", stats.nonFiniteSamples);
    if (!options.quiet && s.integrator == Integrator::Photon) {
        fmt::print(stderr, "photon maps: {} global and {} caustic photons from {} paths in {:.2f} s ({:.1f} MB); radius {:.4g}\n",
                   stats.globalPhotons, stats.causticPhotons, stats.photonPathsTraced, stats.photonSeconds,
                   stats.photonMapBytes / 1048576.0, stats.gatherRadius);
        if (stats.deposit != "all") printDepositStats(stats);
    }
    if (!options.quiet)
        fmt::print(stderr, "wrote {} and {} ({} spp{}, {:.2f} s rendering, {:.2f} Mpaths/s)\n", exrPath.string(),
                   pngPath.string(), stats.samplesPerPixel, stats.partial ? ", partial: " + stats.stopReason : "",
                   stats.renderSeconds, stats.renderSeconds > 0 ? stats.cameraPaths / stats.renderSeconds / 1e6 : 0.0);
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return interruptRequested().load() ? 130 : kExitOk;
}

int runPhotons(const PhotonsCommandOptions& options) {
    const std::filesystem::path output = options.output.empty()
        ? std::filesystem::path("out") / (options.scene.stem().string() + "-photons.ply")
        : options.output;
    if (output.extension() != ".ply")
        throw InputError(fmt::format("-o {}: the photon map is written as .ply", output.string()));
    const Scene scene = loadGltf(options.scene);
    vk::Context context({options.validate, options.device});
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(context, arrays);
    RenderSettings render;  // what the importons need: camera, image, seed, deposit flags
    render.photon = options.deposit;
    render.width = options.width;
    render.height = options.height;
    render.cameraIndex = options.cameraIndex;
    render.seed = options.seed;
    const std::unique_ptr<ImportonMap> importons = makeImportonMap(context, scene, arrays, buffers, render);
    PhotonMapSettings settings;  // every stored photon, in chunks: maps of millions fit
    settings.paths = options.photons;
    settings.maxDeposits = options.maxDeposits;
    settings.seed = options.seed;
    settings.deposit = depositSettings(options.deposit, options.deposit.deposit, importons.get());
    if (options.deposit.deposit == DepositMode::Density)
        settings.cellSize = densityCellSize(options.deposit, options.deposit.gatherK, *importons);
    PhotonMap map(context, scene, arrays, buffers, settings);
    const PhotonMapStats stats = map.build(0);
    const PhotonCounters& c = stats.traced;
    const double seconds = stats.traceSeconds;
    writePhotonPly(output, map.downloadPhotons(), map.photonPower());
    if (stats.dropped > 0)
        fmt::print(stderr, "warning: {} photon(s) did not fit the map ({} photons at most on this device)\n",
                   stats.dropped, map.capacity());
    if (!options.quiet)
        fmt::print(stderr,
                   "traced {} photon paths in {:.2f} s on {}: stored {} caustic, {} global, {} primary; "
                   "absorbed {}, lost {}, truncated {}; wrote {}\n",
                   c.emitted, seconds, context.deviceName(), c.storedCaustic, c.storedGlobal, c.storedPrimary,
                   c.absorbed, c.lost, c.truncated, output.string());
    if (!options.quiet && importons)
        fmt::print(stderr, "deposit {}: kept {} of {} photons ({:.1f} %, {:.1f} MB); {} importons, f = {:.4g}\n",
                   depositModeName(options.deposit.deposit), stats.stored, stats.candidates,
                   stats.candidates ? 100.0 * stats.stored / stats.candidates : 0.0, map.bytes() / 1048576.0,
                   importons->stats().stored, importons->stats().importanceScale);
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return kExitOk;
}

int runGuideGrid(const GuideGridCommandOptions& options) {
    const std::filesystem::path output = options.output.empty()
        ? std::filesystem::path("out") / fmt::format("{}-guide-{}-{}.png", options.scene.stem().string(), options.x, options.y)
        : options.output;
    if (output.extension() != ".png")
        throw InputError(fmt::format("-o {}: the guiding grid is written as .png", output.string()));
    const Scene scene = loadGltf(options.scene);
    const Camera camera = chooseCamera(scene, options.cameraIndex);
    vk::Context context({options.validate, options.device});
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(context, arrays);
    GuideRenderSettings settings = options.guide;
    settings.cache = false;  // the per-vertex grid: the one the paper builds
    const PathGuide guide(context, scene, arrays, buffers, settings, options.seed);
    const GuideGridAtPixel grid =
        guideGridAtPixel(scene, arrays, guide, settings, camera, options.width, options.height, options.x, options.y);
    writePng(output, guideGridImage(grid));
    if (!options.quiet) {
        fmt::print("pixel ({}, {}) sees ({:.3f}, {:.3f}, {:.3f}), normal ({:.2f}, {:.2f}, {:.2f}); {} photons\n", options.x,
                   options.y, grid.position.x, grid.position.y, grid.position.z, grid.normal.x, grid.normal.y,
                   grid.normal.z, grid.photons);
        fmt::print("density relative to cosine sampling, rows: theta bands from the normal, columns: phi sectors\n");
        for (uint32_t i = 0; i < grid.m; ++i) {
            float band = 0.0f;
            std::string row;
            for (uint32_t j = 0; j < grid.n; ++j) {
                row += fmt::format(" {:5.2f}", grid.density[i * grid.n + j]);
                band += grid.density[i * grid.n + j] / float(grid.m * grid.n);
            }
            fmt::print("band {} (probability {:.3f}):{}\n", i, band, row);
        }
        fmt::print("wrote {}\n", output.string());
    }
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return kExitOk;
}

int runDevices() {
    const auto devices = vk::listDevices();
    if (devices.empty()) fmt::print("no Vulkan devices\n");
    for (const auto& d : devices)
        fmt::print("{}: {} ({}, Vulkan {}.{}.{}){}\n", d.index, d.name, d.type, VK_API_VERSION_MAJOR(d.apiVersion),
                   VK_API_VERSION_MINOR(d.apiVersion), VK_API_VERSION_PATCH(d.apiVersion),
                   d.suitable ? "" : " [unsuitable: needs Vulkan 1.3 and a compute queue]");
    return kExitOk;
}

}  // namespace vkp
