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
#include "image/png.h"
#include "render/deposition.h"
#include "render/guide_debug.h"
#include "render/integrators/photon_settings.h"
#include "render/photon_export.h"
#include "render/photon_map.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/check_range.h"
#include "util/errors.h"
#include "vk/context.h"

namespace vkp {
namespace {

using Clock = std::chrono::steady_clock;

std::filesystem::path defaultOutput(const std::filesystem::path& scene) {
    return std::filesystem::path("out") / (scene.stem().string() + ".exr");
}

}  // namespace

void PhotonsCommandOptions::check() const {
    checkRange("--photons", photons, 1u, 1u << 26);
    checkRange("--max-deposits", maxDeposits, 1u, 64u);
    checkRange("--width", width, 1u, 16384u);
    checkRange("--height", height, 1u, 16384u);
    view.check();
    deposit.check();
}

void GuideGridCommandOptions::check() const {
    checkRange("--width", width, 1u, 16384u);
    checkRange("--height", height, 1u, 16384u);
    view.check();
    guide.check();
}

int runRender(const RenderCommandOptions& options, const IntegratorConfig& config) {
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
    chooseCamera(scene, options.frame.cameraIndex, float(options.frame.width) / float(options.frame.height),
                 options.frame.view);

    vk::Context context({options.validate, options.device});
    if (!options.quiet)
        fmt::print(stderr, "vkphoton: {} ({} triangles) on {}{}\n", options.scene.string(),
                   scene.triangles.size(), context.deviceName(), context.validationEnabled() ? " with validation" : "");
    installInterruptHandler();
    Renderer renderer(context, scene);
    const std::unique_ptr<Integrator> integrator = config.create(renderer.gpuScene());
    if (const std::string message = config.startMessage(options.frame); !options.quiet && !message.empty())
        fmt::print(stderr, "{}\n", message);
    ProgressReporter progress("render", options.quiet);
    RenderResult result = renderer.render(
        options.frame, *integrator,
        [&](const RenderProgress& p) { progress.update(p.samplesDone, p.samplesTotal, p.elapsedSeconds); },
        &interruptRequested());
    progress.finish();
    Stats& stats = result.stats;
    const double totalSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats.set("scene", options.scene.string());
    stats.set("timings.loadSeconds", loadSeconds);
    stats.set("timings.totalSeconds", totalSeconds);

    const FrameSettings& frame = options.frame;
    const auto spp = stats.get<uint32_t>("counters.samplesPerPixel");
    const auto renderSeconds = stats.get<double>("timings.renderSeconds");
    const auto partial = stats.get<bool>("partial");
    const auto stopReason = stats.get<std::string>("stopReason");
    std::vector<std::pair<std::string, std::string>> attributes{
        {"vkphoton/scene", options.scene.string()},
        {"vkphoton/integrator", stats.get<std::string>("integrator")},
        {"vkphoton/spp", std::to_string(spp)},
        {"vkphoton/sppRequested", std::to_string(frame.samplesPerPixel)},
        {"vkphoton/seed", std::to_string(frame.seed)},
        {"vkphoton/maxDepth", std::to_string(frame.maxDepth)},
        {"vkphoton/device", stats.get<std::string>("device")},
        {"vkphoton/renderSeconds", fmt::format("{:.3f}", renderSeconds)},
        {"vkphoton/totalSeconds", fmt::format("{:.3f}", totalSeconds)},
        {"vkphoton/partial", partial ? "true" : "false"},
        {"vkphoton/stopReason", stopReason},
        // The PNG's display settings; the EXR's pixels are linear radiance, untouched by them.
        {"vkphoton/exposure", fmt::format("{}", options.display.exposureEv)},
        {"vkphoton/tonemap", viewTransformName(options.display.view)},
    };
    writeExr(exrPath, result.image, attributes);
    writePng(pngPath, result.image, options.display);
    if (!options.statsJson.empty()) {
        nlohmann::json json = stats.toJson();
        json["meanRadiance"] = meanRadiance(result.image);
        writeTextAtomically(options.statsJson, json.dump(2) + "\n");
    }
    for (const std::string& warning : stats.warnings()) fmt::print(stderr, "warning: {}\n", warning);
    if (!options.quiet) {
        for (const std::string& note : stats.notes()) fmt::print(stderr, "{}\n", note);
        fmt::print(stderr, "wrote {} and {} ({} spp{}, {:.2f} s rendering, {:.2f} Mpaths/s)\n", exrPath.string(),
                   pngPath.string(), spp, partial ? ", partial: " + stopReason : "", renderSeconds,
                   stats.get<double>("counters.pathsPerSecond") / 1e6);
    }
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
    FrameSettings frameSettings;  // what the importons see: camera, image, seed
    frameSettings.width = options.width;
    frameSettings.height = options.height;
    frameSettings.cameraIndex = options.cameraIndex;
    frameSettings.view = options.view;
    frameSettings.seed = options.seed;
    const Frame frame = makeFrame(scene, frameSettings);
    vk::Context context({options.validate, options.device});
    const GpuScene gpuScene(context, scene);
    const std::unique_ptr<ImportonMap> importons = makeImportonMap(gpuScene, frame, options.deposit);
    PhotonMapSettings settings;  // every stored photon, in chunks: maps of millions fit
    settings.paths = options.photons;
    settings.maxDeposits = options.maxDeposits;
    settings.seed = options.seed;
    settings.deposit = depositSettings(options.deposit, options.deposit.mode, importons.get());
    if (options.deposit.mode == DepositMode::Density)
        settings.cellSize = densityCellSize(options.deposit, PhotonIntegratorSettings().gatherK, *importons);
    PhotonMap map(context, scene, gpuScene.arrays(), gpuScene.buffers(), settings);
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
                   depositModeName(options.deposit.mode), stats.stored, stats.candidates,
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
    const Camera camera =
        chooseCamera(scene, options.cameraIndex, float(options.width) / float(options.height), options.view);
    vk::Context context({options.validate, options.device});
    const GpuScene gpuScene(context, scene);
    GuideSettings settings = options.guide;
    settings.cache = false;  // the per-vertex grid: the one the paper builds
    const PathGuide guide(gpuScene, settings, options.seed);
    const GuideGridAtPixel grid = guideGridAtPixel(scene, gpuScene.arrays(), guide, settings, camera, options.width,
                                                   options.height, options.x, options.y);
    writePng(output, guideGridImage(grid), DisplaySettings{ViewTransform::Clamp});  // densities scaled to [0, 1]
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
