#include "app/commands.h"

#include <array>
#include <chrono>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/frames_command.h"
#include "app/interrupt.h"
#include "app/progress.h"
#include "image/atomic_file.h"
#include "image/exposure.h"
#include "image/exr.h"
#include "image/metrics.h"
#include "image/png.h"
#include "lights/default_lighting.h"
#include "photon/deposition.h"
#include "guiding/guide_debug.h"
#include "photon/photon_settings.h"
#include "photon/photon_export.h"
#include "app/merge_command.h"
#include "photon/photon_map.h"
#include "render/stats.h"
#include "render/terminations.h"
#include "render/renderer.h"
#include "gpu_scene/scene_buffers.h"
#include "gpu_scene/texture_atlas.h"
#include "scene/gltf_loader.h"
#include "shared/sampling.glsl"
#include "util/check_range.h"
#include "util/errors.h"
#include "util/host_memory.h"
#include "util/printable.h"
#include "vk/context.h"

namespace vkp {
namespace {

std::filesystem::path defaultOutput(const std::filesystem::path& scene) {
    return std::filesystem::path("out") / (scene.stem().string() + ".exr");
}


Scene loadScene(const std::filesystem::path& path, const vk::Context& context, double maxMemoryGiB, int sceneIndex,
                const EnvironmentSettings& environment, bool quiet, const TextureOptions& textures,
                const std::string& variant = {}) {
    GltfLimits limits = deviceSceneLimits(context, maxMemoryGiB);
    limits.sceneIndex = sceneIndex;
    limits.materialVariant = variant;
    Scene scene = loadGltf(path, limits);
    EnvironmentLimits envLimits;
    envLimits.maxMemoryBytes = limits.maxMemoryBytes;
    std::string note;
    applyEnvironment(scene, environment, note, envLimits);
    if (!note.empty() && !quiet) fmt::print(stderr, "{}\n", note);
    if (scene.droppedDegenerateTriangles > 0)
        fmt::print(stderr, "warning: {}: dropped {} degenerate triangle(s)\n", printable(path.string()),
                   scene.droppedDegenerateTriangles);
    if (scene.droppedDuplicateTriangles > 0)
        fmt::print(stderr, "warning: {}: dropped {} triangle(s) identical to an earlier one\n", printable(path.string()),
                   scene.droppedDuplicateTriangles);
    for (const std::string& line : limitTextureSize(scene.textures, textures.maxSize))
        fmt::print(stderr, "warning: texture downscaled: {} (--max-texture-size {})\n", printable(line), textures.maxSize);
    if (!textures.mipmaps) disableMipmaps(scene);
    return scene;
}

}  // namespace

GltfLimits deviceSceneLimits(const vk::Context& context, double maxMemoryGiB) {
    GltfLimits limits;
    limits.deviceMaxTriangles = deviceTriangleLimit(context.properties().limits.maxStorageBufferRange);
    if (maxMemoryGiB > 0.0) limits.maxMemoryBytes = static_cast<uint64_t>(maxMemoryGiB * double(1ull << 30));
    else if (const uint64_t available = hostMemoryAvailable(); available > 0) limits.maxMemoryBytes = available;
    return limits;
}

void PhotonsCommandOptions::check() const {
    checkPhotonPaths(photons, maxDeposits);
    checkRange("--width", width, 1u, 16384u);
    checkRange("--height", height, 1u, 16384u);
    view.check();
    checkRange("--max-memory", maxMemoryGiB, 0.0, 1.0e6);
    environment.check();
    deposit.check();
}

void GuideGridCommandOptions::check() const {
    checkRange("--width", width, 1u, 16384u);
    checkRange("--height", height, 1u, 16384u);
    view.check();
    checkRange("--max-memory", maxMemoryGiB, 0.0, 1.0e6);
    environment.check();
    if (x >= width || y >= height)
        throw InputError(fmt::format("--pixel {} {}: outside the {}x{} image", x, y, width, height));
    guide.check();
}

LightSampler autoLightSampler(const Scene& scene) {
    size_t lights = scene.lights.size();
    for (const Triangle& t : scene.triangles)
        if (gpu::luminance(scene.materials[t.material].emissive) > 0.0f) ++lights;
    return lights > kAutoBvhLights ? LightSampler::Bvh : LightSampler::Power;
}

void checkRenderOutputs(const RenderCommandOptions& options, const std::vector<std::filesystem::path>& exrs) {
    for (const std::filesystem::path& exr : exrs) {
        if (exr.extension() != ".exr")
            throw InputError(fmt::format("-o {}: the output must end in .exr (a .png is written beside it)", exr.string()));
        std::filesystem::path png = exr;
        png.replace_extension(".png");
        checkWritable(exr);
        checkWritable(png);
    }
    if (!options.statsJson.empty()) checkWritable(options.statsJson);
    // `vkphoton merge` joins the beauty image only; parts with AOV layers would lose them.
    if (options.aov.any() && options.frame.crop)
        throw InputError("--aov cannot be combined with --tile or --crop: vkphoton merge joins the image only");
    options.lightSampling.check();
}

int runRender(const RenderCommandOptions& options, const IntegratorConfig& config) {
    if (options.frames) return runRenderFrames(options, config);
    const auto start = Clock::now();
    const std::filesystem::path exrPath = options.output.empty() ? defaultOutput(options.scene) : options.output;
    std::filesystem::path pngPath = exrPath;
    pngPath.replace_extension(".png");
    checkRenderOutputs(options, {exrPath});
    // Signals from here on stop the work and write what there is (app/interrupt.h).
    installInterruptHandler();

    // The device first: its limits bound the scene before it is decoded.
    vk::Context context({options.validate, options.device});
    Scene scene = loadScene(options.scene, context, options.maxMemoryGiB, options.sceneIndex, options.environment, options.quiet,
                              options.textures, options.variant);
    scene.energyCompensation = !options.noEnergyCompensation;
    const double loadSeconds = secondsSince(start);
    // Validate the camera choice before the expensive set-up.
    chooseCamera(scene, options.frame.cameraIndex, float(options.frame.width) / float(options.frame.height),
                 options.frame.view);

    if (!options.quiet)
        fmt::print(stderr, "vkphoton: {} ({} triangles{}) on {}{}\n", printable(options.scene.string()),
                   scene.triangles.size(),
                   scene.instances.empty() ? std::string()
                                           : fmt::format(", {} instances of {} meshes", scene.instances.size(),
                                                         scene.meshes.size()),
                   context.deviceName(), context.validationEnabled() ? " with validation" : "");
    LightSampling lightSampling = options.lightSampling;
    if (options.lightSamplerAuto) lightSampling.sampler = autoLightSampler(scene);
    Renderer renderer(context, scene, lightSampling);
    FrameSettings frameSettings = options.frame;
    frameSettings.timeLimitFrom = start;  // --time-limit counts from the start of the command
    const std::unique_ptr<Integrator> integrator = config.create(renderer.gpuScene());
    if (const std::string message = config.startMessage(options.frame); !options.quiet && !message.empty())
        fmt::print(stderr, "{}\n", message);
    ProgressReporter progress("render", options.quiet);
    RenderResult result = renderer.render(
        frameSettings, *integrator,
        [&](const RenderProgress& p) { progress.update(p.samplesDone, p.samplesTotal, p.elapsedSeconds); },
        &interruptRequested());
    progress.finish();
    Stats& stats = result.stats;
    const double totalSeconds = secondsSince(start);
    stats.set("scene", options.scene.string());
    stats.set("timings.loadSeconds", loadSeconds);
    stats.set("timings.totalSeconds", totalSeconds);

    // --exposure auto: metered on this image (a part of an image meters its window; `vkphoton
    // merge` meters the joined image again).
    // Under a constant environment its pixels are the backdrop, which the meter leaves out.
    const std::optional<glm::vec3> backdrop = scene.environment.present && scene.environment.width == 0
                                                  ? std::optional<glm::vec3>(scene.environment.radiance)
                                                  : std::nullopt;
    const DisplaySettings display = resolveExposure(options.display, result.image, backdrop);
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
        {"vkphoton/tonemap", viewTransformName(options.display.view)},
        {"vkphoton/environment", scene.environment.present ? scene.environment.source : "none"},
        {"vkphoton/materialVariant", options.variant.empty() ? "none" : options.variant},
    };
    for (auto& attribute : exposureAttributes(display, backdrop)) attributes.push_back(std::move(attribute));
    stats.set("display.exposure", double(display.exposureEv));
    stats.set("display.exposureMode", std::string(display.autoExposure ? "auto" : "fixed"));
    // --tile / --crop: where the part belongs, for `vkphoton merge` (app/merge_command.h).
    for (auto& attribute : partAttributes(frame, stats)) attributes.push_back(std::move(attribute));
    if (frame.crop) stats.set("crop", frame.crop->text());
    std::vector<ExrChannel> aovs;
    if (options.aov.any()) {
        const Frame aovFrame = makeFrame(scene, frameSettings);
        aovs = aovChannels(renderAovs(renderer.gpuScene(), aovFrame), options.aov);
    }
    // Both or neither: a signal or a failure never leaves a new EXR beside an old PNG.
    writeFilesTogether({{exrPath, exrBytes(exrPath, result.image, attributes, aovs)},
                        {pngPath, pngBytes(pngPath, result.image, display)}});
    if (!options.statsJson.empty()) {
        nlohmann::json json = stats.toJson();
        json["meanRadiance"] = meanRadiance(result.image);
        const DisplayStatistics shown = displayStatistics(result.image, display);
        json["display"]["meanValue"] = shown.mean;            // the PNG's mean 8-bit value / 255
        json["display"]["saturatedPixels"] = shown.saturated;  // share of its pixels with a channel at 255
        writeTextAtomically(options.statsJson, json.dump(2) + "\n");
    }
    for (const std::string& warning : stats.warnings()) fmt::print(stderr, "warning: {}\n", warning);
    if (!options.quiet) {
        for (const std::string& note : stats.notes()) fmt::print(stderr, "{}\n", note);
        if (display.autoExposure)
            fmt::print(stderr, "exposure auto: EV {:+.2f} (the PNG; --exposure EV fixes it)\n", display.exposureEv);
        fmt::print(stderr, "wrote {} and {} ({} spp{}, {:.2f} s rendering, {:.2f} Mpaths/s)\n", printable(exrPath.string()),
                   printable(pngPath.string()), spp, partial ? ", partial: " + stopReason : "", renderSeconds,
                   stats.get<double>("counters.pathsPerSecond") / 1e6);
    }
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return interruptRequested().load() ? interruptExitCode() : kExitOk;
}

int runPhotons(const PhotonsCommandOptions& options) {
    const std::filesystem::path output = options.output.empty()
        ? std::filesystem::path("out") / (options.scene.stem().string() + "-photons.ply")
        : options.output;
    if (output.extension() != ".ply")
        throw InputError(fmt::format("-o {}: the photon map is written as .ply", output.string()));
    checkWritable(output);
    installInterruptHandler();
    vk::Context context({options.validate, options.device});
    const Scene scene = loadScene(options.scene, context, options.maxMemoryGiB, options.sceneIndex, options.environment, options.quiet,
                              options.textures);
    FrameSettings frameSettings;  // what the importons see: camera, image, seed
    frameSettings.width = options.width;
    frameSettings.height = options.height;
    frameSettings.cameraIndex = options.cameraIndex;
    frameSettings.view = options.view;
    frameSettings.seed = options.seed;
    const Frame frame = makeFrame(scene, frameSettings);
    const GpuScene gpuScene(context, scene);
    const std::unique_ptr<ImportonMap> importons = makeImportonMap(gpuScene, frame, options.deposit);
    PhotonMapSettings settings;  // every stored photon, in chunks: maps of millions fit
    settings.paths = options.photons;
    settings.maxDeposits = options.maxDeposits;
    settings.seed = options.seed;
    RenderControl control;  // Ctrl-C keeps the chunks traced so far
    control.stop = &interruptRequested();
    settings.control = &control;
    settings.deposit = depositSettings(options.deposit, options.deposit.mode, importons.get());
    if (options.deposit.mode == DepositMode::Density)
        settings.cellSize = densityCellSize(options.deposit, PhotonIntegratorSettings().gatherK, *importons);
    PhotonMap map(context, scene, gpuScene.arrays(), gpuScene.buffers(), settings);
    const PhotonMapStats stats = map.build(0);
    const PhotonCounters& c = stats.traced;
    const double seconds = stats.traceSeconds;
    writePhotonPly(output, map.downloadPhotons(), map.photonPower());
    if (stats.dropped > 0)
        fmt::print(stderr, "warning: {} photon(s) did not fit the map ({} photons at most: paths x --max-deposits, 2^31)\n",
                   stats.dropped, map.capacity());
    Stats terminations;  // the context's counters start at zero: importons and photons of this run
    reportTerminations(readTerminations(context), terminations);
    for (const std::string& warning : terminations.warnings()) fmt::print(stderr, "warning: {}\n", warning);
    if (!options.quiet)
        fmt::print(stderr,
                   "traced {} photon paths in {:.2f} s on {}: stored {} caustic, {} global, {} primary; "
                   "absorbed {}, lost {}, truncated {}; {} paths sampled into their --max-deposits slots; map {} photons, "
                   "{:.1f} MiB with its grid; peak device memory {:.1f} MiB; wrote {}\n",
                   c.emitted, seconds, context.deviceName(), c.storedCaustic, c.storedGlobal, c.storedPrimary,
                   c.absorbed, c.lost, c.truncated, c.sampled, stats.stored, stats.bytes / 1048576.0,
                   context.memory().peak() / 1048576.0, printable(output.string()));
    if (!options.quiet && importons)
        fmt::print(stderr, "deposit {}: kept {} of {} photons ({:.1f} %, {:.1f} MB); {} importons, f = {:.4g}\n",
                   depositModeName(options.deposit.mode), stats.stored, stats.candidates,
                   stats.candidates ? 100.0 * stats.stored / stats.candidates : 0.0, map.bytes() / 1048576.0,
                   importons->stats().stored, importons->stats().importanceScale);
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return interruptRequested().load() ? interruptExitCode() : kExitOk;
}

int runGuideGrid(const GuideGridCommandOptions& options) {
    const std::filesystem::path output = options.output.empty()
        ? std::filesystem::path("out") / fmt::format("{}-guide-{}-{}.png", options.scene.stem().string(), options.x, options.y)
        : options.output;
    if (output.extension() != ".png")
        throw InputError(fmt::format("-o {}: the guiding grid is written as .png", output.string()));
    checkWritable(output);
    installInterruptHandler();
    vk::Context context({options.validate, options.device});
    const Scene scene = loadScene(options.scene, context, options.maxMemoryGiB, options.sceneIndex, options.environment, options.quiet,
                              options.textures);
    const Camera camera =
        chooseCamera(scene, options.cameraIndex, float(options.width) / float(options.height), options.view);
    const GpuScene gpuScene(context, scene);
    GuideSettings settings = options.guide;
    settings.cache = false;  // the per-vertex grid: the one the paper builds
    RenderControl control;  // Ctrl-C: the grid of the photons traced so far
    control.stop = &interruptRequested();
    const PathGuide guide(gpuScene, settings, options.seed, &control);
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
        fmt::print("wrote {}\n", printable(output.string()));
    }
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return interruptRequested().load() ? interruptExitCode() : kExitOk;
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
