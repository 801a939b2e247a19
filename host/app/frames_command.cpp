#include "app/frames_command.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/interrupt.h"
#include "app/merge_command.h"
#include "app/progress.h"
#include "image/atomic_file.h"
#include "image/exposure.h"
#include "image/exr.h"
#include "image/metrics.h"
#include "image/png.h"
#include "lights/default_lighting.h"
#include "render/aov.h"
#include "animation/frame_scene.h"
#include "animation/frame_update.h"
#include "render/renderer.h"
#include "animation/selective_frame_update.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"
#include "util/printable.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace vkp {

std::filesystem::path framesOutputPattern(const RenderCommandOptions& options) {
    if (options.output.empty())
        return std::filesystem::path("out") / (options.scene.stem().string() + "-####.exr");
    if (!hasFramePattern(options.output))
        throw InputError(fmt::format("-o {}: with --frames the file name needs a run of '#' for the frame number "
                                     "(e.g. out/frame-####.exr)",
                                     options.output.string()));
    return options.output;
}

int runRenderFrames(const RenderCommandOptions& options, const IntegratorConfig& config) {
    const auto start = Clock::now();
    const FrameRange range = *options.frames;
    if (!(options.fps > 0.0 && options.fps <= 1000.0))
        throw InputError(fmt::format("--fps {}: must be in (0, 1000]", options.fps));
    const std::filesystem::path pattern = framesOutputPattern(options);
    if (pattern.extension() != ".exr")
        throw InputError(fmt::format("-o {}: the output must end in .exr (a .png is written beside it)", pattern.string()));
    // The first and the last frame's files stand for all (the same folder, the same pattern).
    checkRenderOutputs(options, {frameOutputPath(pattern, range.first), frameOutputPath(pattern, range.last)});
    installInterruptHandler();

    vk::Context context({options.validate, options.device});
    GltfLimits limits = deviceSceneLimits(context, options.maxMemoryGiB);
    limits.sceneIndex = options.sceneIndex;
    limits.materialVariant = options.variant;
    GltfSceneSource source(options.scene, limits);
    SceneAnimation& animation = source.animation();
    animation.select(options.animation);
    if (animation.empty())
        fmt::print(stderr, "warning: {}: the file has no animations: every frame shows the still scene\n",
                   printable(options.scene.string()));
    const double loadSeconds = secondsSince(start);
    if (!options.quiet)
        fmt::print(stderr, "vkphoton: {} frames {}..{} at {} fps (animation {}, keys {:.3f}..{:.3f} s) on {}{}\n",
                   printable(options.scene.string()), range.first, range.last, options.fps,
                   options.animation < 0 ? std::string("all") : std::to_string(options.animation),
                   animation.startTime(), animation.endTime(), context.deviceName(),
                   context.validationEnabled() ? " with validation" : "");

    // Every frame takes the still scene's bounds (they set the photon radius, the directional
    // lights' disk, the raster near plane and, without a camera in the file, the framing): so
    // they do not depend on the frame or the range rendered, and frame N of a sequence equals
    // frame N rendered alone. Without a camera in the file every frame keeps the still framing.
    FrameSettings frameSettings = options.frame;
    LightSampling lightSampling = options.lightSampling;
    Bounds stillBounds;
    // The environment too, chosen once for the still scene: the default sky never switches on or
    // off between frames, and every range of a split sequence chooses the same.
    Environment environment;
    std::vector<int> backdropNodes;  // sky boxes, found once with the environment
    {
        Scene still = source.stillScene();
        stillBounds = still.bounds;
        std::string note;
        applyEnvironment(still, options.environment, note);
        if (!note.empty() && !options.quiet) fmt::print(stderr, "{}\n", note);
        environment = still.environment;
        backdropNodes = still.backdropNodes;
        if (still.cameras.empty()) {
            const Camera fixed = chooseCamera(still, options.frame.cameraIndex,
                                              float(options.frame.width) / float(options.frame.height), options.frame.view);
            frameSettings.view.lookFrom = fixed.position;
            frameSettings.view.lookAt = fixed.position + fixed.forward;
            frameSettings.view.fovDegrees = glm::degrees(fixed.yfov);
        }
        if (options.lightSamplerAuto) lightSampling.sampler = autoLightSampler(still);
    }
    // One scene (BVH, buffers), integrator and kernels for the sequence, updated in place per
    // frame (animation/frame_scene.h); rebuilt only when a frame changes what cannot be updated.
    FrameScene frameScene(context, lightSampling, options.sceneRebuildEachFrame);
    std::unique_ptr<Integrator> integrator;
    // --photon-update: full retrace per frame, or the selective update (animation/selective_frame_update.h).
    std::unique_ptr<FrameUpdate> updateOwner;
    if (options.photonUpdateFull) {
        updateOwner = std::make_unique<FrameUpdate>();
    } else {
        SelectiveUpdateOptions selective;
        selective.budget = options.photonBudget;
        selective.groups = options.photonGroups;
        selective.trackPaths = !options.photonDetectPilots;
        selective.verify = options.verifyUpdate;
        updateOwner = std::make_unique<SelectiveFrameUpdate>(context, selective);
    }
    FrameUpdate& update = *updateOwner;
    nlohmann::json frames = nlohmann::json::array();
    uint64_t verifiedStalePhotons = 0, verifiedFramesStale = 0;  // --verify-update, over the frames
    nlohmann::json lastStats;
    uint32_t written = 0;
    for (uint32_t f = range.first; f <= range.last && !interruptRequested().load(); ++f) {
        const auto frameStart = Clock::now();
        const double time = frameTime(f, options.fps);
        Scene scene = source.sceneAt(time);
        scene.environment = environment;
        scene.backdropNodes = backdropNodes;
        scene.energyCompensation = !options.noEnergyCompensation;
        scene.bounds = stillBounds;
        const double flattenSeconds = secondsSince(frameStart);
        const auto buildStart = Clock::now();
        const FrameSceneChange change = frameScene.set(std::move(scene));
        if (change.rebuilt) {
            integrator.reset();
            integrator = config.create(frameScene.renderer().gpuScene());
            if (!options.quiet && f != range.first)
                fmt::print(stderr, "frame {}: scene rebuilt: {}\n", f, change.reason);
        }
        const double sceneUpdateSeconds = flattenSeconds + secondsSince(buildStart);
        Renderer& renderer = frameScene.renderer();
        FrameSettings settings = frameSettings;
        settings.photonUpdate = &update;
        settings.update = {f, time, f == range.first, frameScene.generation()};
        ProgressReporter progress(fmt::format("frame {}", f), options.quiet);
        RenderResult result = renderer.render(
            settings, *integrator,
            [&](const RenderProgress& p) { progress.update(p.samplesDone, p.samplesTotal, p.elapsedSeconds); },
            &interruptRequested());
        progress.finish();
        // Ctrl-C: the finished frames stay; the interrupted one is not written.
        if (interruptRequested().load()) break;
        Stats& stats = result.stats;
        const FramePhotonCounts counts = update.takeCounts();
        const uint64_t photonPaths = counts.photonPathsTraced > 0 || !stats.has("photons.pathsTraced")
            ? counts.photonPathsTraced
            : stats.get<uint64_t>("photons.pathsTraced");
        const double seconds = secondsSince(frameStart);
        stats.set("scene", options.scene.string());
        stats.set("timings.loadSeconds", loadSeconds);
        const std::filesystem::path exrPath = frameOutputPath(pattern, f);
        std::filesystem::path pngPath = exrPath;
        pngPath.replace_extension(".png");
        ExrAttributes attributes{
            {"vkphoton/scene", options.scene.string()},
            {"vkphoton/integrator", stats.get<std::string>("integrator")},
            {"vkphoton/frame", std::to_string(f)},
            {"vkphoton/time", fmt::format("{}", time)},
            {"vkphoton/spp", std::to_string(stats.get<uint32_t>("counters.samplesPerPixel"))},
            {"vkphoton/seed", std::to_string(settings.seed)},
            {"vkphoton/device", stats.get<std::string>("device")},
            {"vkphoton/partial", stats.get<bool>("partial") ? "true" : "false"},
            {"vkphoton/stopReason", stats.get<std::string>("stopReason")},
        };
        // --exposure auto meters each frame on its own, so frame N still equals frame N rendered
        // alone; a sequence that must not change exposure takes a fixed --exposure EV.
        const Environment& environment = frameScene.scene().environment;
        const std::optional<glm::vec3> backdrop =
            environment.present && environment.width == 0 ? std::optional<glm::vec3>(environment.radiance) : std::nullopt;
        const DisplaySettings display = resolveExposure(options.display, result.image, backdrop);
        for (auto& attribute : exposureAttributes(display, backdrop)) attributes.push_back(std::move(attribute));
        attributes.emplace_back("vkphoton/tonemap", viewTransformName(display.view));
        // --tile / --crop: the same part of every frame, with what `vkphoton merge` needs.
        for (auto& attribute : partAttributes(settings, stats)) attributes.push_back(std::move(attribute));
        if (settings.crop) stats.set("crop", settings.crop->text());
        std::vector<ExrChannel> aovs;
        if (options.aov.any())
            aovs = aovChannels(renderAovs(renderer.gpuScene(), makeFrame(frameScene.scene(), settings)), options.aov);
        writeFilesTogether({{exrPath, exrBytes(exrPath, result.image, attributes, aovs)},
                            {pngPath, pngBytes(pngPath, result.image, display)}});
        ++written;
        frames.push_back({{"frame", f},
                          {"time", time},
                          {"photonPathsTraced", photonPaths},
                          {"groupsRetraced", counts.groupsRetraced},
                          {"changedPilots", counts.changedPilots},
                          {"groupsMarked", counts.groupsMarked},
                          {"groupsPending", counts.groupsPending},
                          {"stalePathsFound", counts.stalePathsFound},
                          {"stalePathsLeft", counts.stalePathsLeft},
                          {"detectSeconds", counts.detectSeconds},
                          {"seconds", seconds},
                          {"sceneUpdateSeconds", sceneUpdateSeconds},
                          {"flattenSeconds", flattenSeconds},
                          {"sceneRebuilt", change.rebuilt},
                          {"sceneRebuildReason", change.rebuilt ? change.reason : std::string()},
                          {"bvhSeconds", change.bvhSeconds},
                          {"uploadSeconds", change.uploadSeconds},
                          {"lightCellSeconds", change.lightCellSeconds},
                          {"renderSeconds", stats.get<double>("timings.renderSeconds")},
                          {"triangles", renderer.gpuScene().arrays().triangles.size()},
                          {"partial", stats.get<bool>("partial")},
                          {"meanRadiance", meanRadiance(result.image)},
                          {"exposure", display.exposureEv},
                          {"output", exrPath.string()}});
        if (options.verifyUpdate) {  // per map and in total; a summary line per frame
            nlohmann::json maps = nlohmann::json::array();
            uint64_t stalePhotons = 0, stalePaths = 0, staleGroups = 0;
            for (const MapVerification& v : counts.verification) {
                maps.push_back({{"map", v.map}, {"paths", v.paths}, {"stalePhotons", v.stalePhotons},
                                {"stalePaths", v.stalePaths}, {"staleGroups", v.staleGroups}});
                stalePhotons += v.stalePhotons;
                stalePaths += v.stalePaths;
                staleGroups += v.staleGroups;
            }
            frames.back()["verify"] = {{"maps", maps}, {"stalePhotons", stalePhotons}, {"stalePaths", stalePaths},
                                       {"staleGroups", staleGroups}};
            verifiedStalePhotons += stalePhotons;
            verifiedFramesStale += stalePhotons > 0 ? 1 : 0;
            fmt::print(stderr, "frame {}: verify-update: {} stale photons in {} paths ({} groups) over {} maps\n", f,
                       stalePhotons, stalePaths, staleGroups, counts.verification.size());
        }
        for (const std::string& warning : stats.warnings()) fmt::print(stderr, "warning: frame {}: {}\n", f, warning);
        if (!options.quiet)
            fmt::print(stderr, "frame {} (t = {:.3f} s): wrote {} ({:.2f} s, scene update {:.3f} s, {} photon paths)\n", f,
                       time, printable(exrPath.string()), seconds, sceneUpdateSeconds, photonPaths);
        lastStats = stats.toJson();
    }
    if (!options.statsJson.empty()) {
        nlohmann::json json = lastStats.is_null() ? nlohmann::json::object() : lastStats;  // the last frame's details
        json["frames"] = frames;
        json["settings"]["frames"] = {{"first", range.first}, {"last", range.last}, {"fps", options.fps},
                                      {"animation", options.animation}};
        json["timings"]["totalSeconds"] = secondsSince(start);
        if (options.verifyUpdate)
            json["verifyUpdate"] = {{"stalePhotons", verifiedStalePhotons}, {"framesWithStalePhotons", verifiedFramesStale}};
        writeTextAtomically(options.statsJson, json.dump(2) + "\n");
    }
    if (options.verifyUpdate)
        fmt::print(stderr, "verify-update: {} stale photons in {} of {} frame(s)\n", verifiedStalePhotons,
                   verifiedFramesStale, written);
    if (!options.quiet)
        fmt::print(stderr, "wrote {} of {} frame(s) in {:.2f} s\n", written, range.count(), secondsSince(start));
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return interruptRequested().load() ? interruptExitCode() : kExitOk;
}

}  // namespace vkp
