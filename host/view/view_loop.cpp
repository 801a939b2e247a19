#include <algorithm>
#include <future>
#include <memory>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "image/atomic_file.h"
#include "image/exr.h"
#include "image/png.h"
#include "image/view_transform.h"
#include "lights/default_lighting.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"
#include "util/printable.h"
#include "view/camera_controller.h"
#include "view/display_pass.h"
#include "view/event_script.h"
#include "view/node_picking.h"
#include "view/progressive_session.h"
#include "view/script_player.h"
#include "view/swapchain_presenter.h"
#include "view/view_command.h"
#include "view/view_stats.h"
#include "view/view_window.h"
#include "vk/context.h"

namespace vkp {
namespace {

// Each loop iteration aims to take this long: it renders for what is left of it after showing
// the last image, then presents and polls the window again. Where showing is slow (lavapipe at
// large sizes) it renders at least kRenderPerShow times as long as showing took, so showing takes
// at most a quarter of the time, and never less than kMinRenderSeconds.
constexpr double kFrameSeconds = 1.0 / 60.0;
constexpr double kRenderPerShow = 3.0;
constexpr double kMinRenderSeconds = 1.0 / 240.0;
// With nothing left to render the loop waits this long for input.
constexpr double kIdleSeconds = 0.05;

// EXR and PNG side by side, as `render` writes them (PATH may name either).
void writeScreenshot(const std::filesystem::path& path, const ImageRgb& image, const ViewCommandOptions& options,
                     ProgressiveSession& session) {
    std::filesystem::path exr = path, png = path;
    exr.replace_extension(".exr");
    png.replace_extension(".png");
    if (exr.has_parent_path()) std::filesystem::create_directories(exr.parent_path());
    const FrameSettings& frame = session.settings().frame;
    const ExrAttributes attributes{
        {"vkphoton/scene", options.render.scene.string()},
        {"vkphoton/integrator", session.integratorName()},
        {"vkphoton/spp", std::to_string(session.samples())},
        {"vkphoton/sppRequested", std::to_string(frame.samplesPerPixel)},
        {"vkphoton/seed", std::to_string(frame.seed)},
        {"vkphoton/maxDepth", std::to_string(frame.maxDepth)},
        {"vkphoton/device", session.context().deviceName()},
        {"vkphoton/exposure", fmt::format("{}", options.render.display.exposureEv)},
        {"vkphoton/tonemap", viewTransformName(options.render.display.view)},
        {"vkphoton/source", "view"},
    };
    writeFilesTogether({{exr, exrBytes(exr, image, attributes)}, {png, pngBytes(png, image, options.render.display)}});
}

// The script's checks that need the scene and the window size: nodes that exist, pixels inside.
void checkScript(const std::vector<ScriptEvent>& events, const GltfSceneSource& source, uint32_t width, uint32_t height) {
    auto inside = [&](glm::vec2 p) { return p.x >= 0.0f && p.y >= 0.0f && p.x < float(width) && p.y < float(height); };
    for (const ScriptEvent& e : events) {
        if (e.command == ScriptCommand::Resize) {  // later pixels are in the resized window
            width = uint32_t(e.from.x);
            height = uint32_t(e.from.y);
        }
        if (e.command == ScriptCommand::Move && source.findNode(e.node) < 0)
            throw InputError(fmt::format("{}: move: unknown node '{}' (no glTF node has that name)", e.where,
                                         printable(e.node)));
        if ((e.command == ScriptCommand::Click || e.command == ScriptCommand::Drag) && !inside(e.from))
            throw InputError(fmt::format("{}: ({}, {}) is outside the {}x{} window", e.where, e.from.x, e.from.y, width,
                                         height));
        if (e.command == ScriptCommand::Drag && !inside(e.to))
            throw InputError(fmt::format("{}: ({}, {}) is outside the {}x{} window", e.where, e.to.x, e.to.y, width,
                                         height));
        if (e.command == ScriptCommand::Screenshot) {
            std::filesystem::path exr = e.path, png = e.path;
            exr.replace_extension(".exr");
            png.replace_extension(".png");
            for (const auto& p : {exr, png})
                if (p.has_parent_path() && std::filesystem::exists(p.parent_path())) checkWritable(p);
        }
    }
}

}  // namespace

int runView(const ViewCommandOptions& options,
            const std::vector<std::pair<std::string, const IntegratorConfig*>>& integrators, size_t first) {
    const auto start = Clock::now();
    const RenderCommandOptions& render = options.render;
    const std::vector<ScriptEvent> events = options.events.empty() ? std::vector<ScriptEvent>{}
                                                                   : readEventScript(options.events);
    if (!render.statsJson.empty()) checkWritable(render.statsJson);
    if (!options.headless) requireDisplay();
    // The display transform's lattice (a few hundred thousand evaluations) while the scene loads.
    auto lattice = std::async(std::launch::async, displayLattice, render.display.view);
    uint32_t width = render.frame.width, height = render.frame.height;  // the window's (and the image's) size
    const std::string sceneName = render.scene.filename().string();
    // --headless: no window; the script drives the view and images go to an offscreen image.
    const std::unique_ptr<ViewWindow> window =
        options.headless ? nullptr : std::make_unique<ViewWindow>(width, height, fmt::format("vkphoton view: {}", sceneName));
    nlohmann::json startup;  // where the time to the first image goes (--stats-json "startup")
    startup["windowSeconds"] = secondsSince(start);

    vk::ContextOptions contextOptions{render.validate, render.device};
    if (window) {
        contextOptions.instanceExtensions = ViewWindow::requiredInstanceExtensions();
        contextOptions.canPresent = &ViewWindow::canPresent;
    }
    vk::Context context(contextOptions);
    startup["deviceSeconds"] = secondsSince(start);
    GltfLimits limits = deviceSceneLimits(context, render.maxMemoryGiB);
    limits.sceneIndex = render.sceneIndex;
    limits.instanceEveryMesh = true;  // any node can be moved in place
    GltfSceneSource source(render.scene, limits);
    checkScript(events, source, width, height);
    source.animation().select(render.animation);

    // As `render --frames` does: every scene takes the still scene's bounds (photon radius,
    // framing, the directional lights' disk), so moving a node changes nothing else.
    Scene still = source.stillScene();
    const Bounds stillBounds = still.bounds;
    SessionSettings settings;
    settings.frame = render.frame;
    settings.lightSampling = render.lightSampling;
    if (render.lightSamplerAuto) settings.lightSampling.sampler = autoLightSampler(still);
    settings.selective.budget = render.photonBudget;
    settings.selective.groups = render.photonGroups;
    settings.preview = options.preview;
    settings.sampleParts = options.sampleParts;
    // The environment is chosen once, for the scene as loaded: a move never switches the default
    // sky on or off (nor traces the emitters' landing again).
    std::optional<Environment> environment;
    std::vector<int> backdropNodes;  // sky boxes, found once with the environment
    auto prepared = [&](Scene scene) {
        if (!environment) {
            std::string note;
            applyEnvironment(scene, render.environment, note);
            if (!note.empty() && !render.quiet) fmt::print(stderr, "{}\n", note);
            environment = scene.environment;
            backdropNodes = scene.backdropNodes;
        } else {
            scene.environment = *environment;
            scene.backdropNodes = backdropNodes;
        }
        scene.energyCompensation = !render.noEnergyCompensation;
        scene.bounds = stillBounds;
        return scene;
    };
    const Camera initialCamera =
        chooseCamera(still, render.frame.cameraIndex, float(width) / float(height), render.frame.view);
    CameraController camera(initialCamera, render.frame.view.lookAt.value_or(stillBounds.center()));

    startup["loadSeconds"] = secondsSince(start);
    ProgressiveSession session(context, settings);
    session.setScene(prepared(std::move(still)));
    startup["sceneSeconds"] = secondsSince(start);  // BVH, upload
    size_t integratorIndex = first;
    session.setIntegrator(*integrators[integratorIndex].second);
    startup["integratorSeconds"] = secondsSince(start);  // its kernels (pipelines compiled on first use)
    SwapchainPresenter presenter(context, window ? window->createSurface(context.instance()) : VK_NULL_HANDLE, width,
                                 height);
    const std::vector<glm::vec4> displayTable = lattice.get();
    auto display = std::make_unique<DisplayPass>(context, width, height, displayTable);
    startup["presenterSeconds"] = secondsSince(start);  // the surface, swapchain and display pass
    if (!render.quiet)
        fmt::print(stderr, "vkphoton view: {} on {}{}{}\n", printable(render.scene.string()), context.deviceName(),
                   context.validationEnabled() ? " with validation" : "",
                   window ? "; press H for help" : ", headless (images offscreen)");
    session.restart(PhotonRefresh::Full);
    startup["restartSeconds"] = secondsSince(start);  // frame, raster light, film; the preview or the preparation
    // Photon maps, raster light (set once the integrator is prepared: after the preview, if any).
    auto startupPrepared = [&]() {
        startup["prepareSeconds"] = session.lastPrepareSeconds();
        startup["photonPathsTraced"] = session.lastPhotonPaths();
    };
    if (!session.inPreview()) startupPrepared();

    ViewStats stats(start);
    GltfSceneSource::NodeOffsets offsets;
    int selected = -1;
    bool playing = false;
    double animationTime = 0.0;
    bool animated = false;  // the scene shows the animation at animationTime (else the still pose)
    auto lastTick = Clock::now();
    ScriptPlayer script(events);
    uint32_t shownSamples = UINT32_MAX;        // samples of the image on screen (UINT32_MAX: none yet)
    bool redraw = true;
    uint32_t screenshots = 0;
    double showSeconds = 0.0;  // what the last image took to show (display pass, copy, present)
    auto restartAt = Clock::now();  // when the current accumulation's samples began
    bool quit = false;

    auto sceneNow = [&]() {
        return prepared(animated ? source.sceneAt(animationTime, &offsets) : source.stillScene(&offsets));
    };
    auto updateMask = [&]() {
        display->setMask(selected >= 0 ? nodeMask(session.scene(), session.arrays(), session.frame().gpuCamera, width,
                                                 height, selected)
                                      : std::vector<uint8_t>());
        redraw = true;
    };
    // A change: restart the accumulation and record it.
    auto applyChange = [&](const std::string& kind, PhotonRefresh refresh) {
        const auto at = Clock::now();
        session.restart(refresh);
        stats.change(kind, at, session.lastPhotonPaths(), session.lastFullPhotonPaths(), session.lastPrepareSeconds());
        shownSamples = UINT32_MAX;
        restartAt = Clock::now();
        if (selected >= 0) updateMask();
    };
    auto moveNode = [&](int node, glm::dvec3 delta) {
        if (offsets.size() <= size_t(node)) offsets.resize(size_t(node) + 1, glm::dvec3(0.0));
        offsets[node] += delta;
    };

    std::vector<ViewAction> deferred;  // input that arrived while the integrator prepared
    auto lastTitle = Clock::now();
    auto closeRequested = [&]() { return window && window->closeRequested(); };
    auto setTitle = [&](const std::string& title) {
        if (window) window->setTitle(title);
    };
    while (!quit && !closeRequested()) {
        std::vector<ViewAction> actions = window ? window->poll() : std::vector<ViewAction>();
        bool justPrepared = false;
        if (session.preparing()) {
            session.step(0.0);  // finds the preparation done (or rethrows its error)
            if (session.preparing()) {
                // The window stays responsive: input is kept for when the preparation is done,
                // Q or Esc stop it.
                for (const ViewAction& a : actions) {
                    if (a.kind == ViewAction::Kind::Key && a.key == ViewKey::Quit) quit = true;
                    deferred.push_back(a);
                }
                if (quit || closeRequested()) {
                    session.cancel();
                    break;
                }
                if (secondsSince(lastTitle) > 0.5) {
                    setTitle(fmt::format("vkphoton view: {} | {} | {} ({:.0f} s){}", sceneName,
                                                session.integratorName(),
                                                session.inPreview() ? "preparing" : "tracing a pass's photons",
                                                secondsSince(restartAt),
                                                deferred.empty() ? std::string() : ", input queued"));
                    lastTitle = Clock::now();
                }
                std::this_thread::sleep_for(std::chrono::duration<double>(kIdleSeconds));
                continue;
            }
            justPrepared = session.preparedNow();
        }
        if (!deferred.empty()) {
            actions.insert(actions.begin(), deferred.begin(), deferred.end());
            deferred.clear();
        }
        if (justPrepared) {  // the restart's own counts are known now
            shownSamples = UINT32_MAX;  // its first image is not on screen yet (a refresh round waits for it)
            if (session.lastWasRefresh()) stats.refresh(session.lastPhotonPaths());
            else if (stats.changes().empty()) startupPrepared();
            else stats.prepared(session.lastPhotonPaths(), session.lastFullPhotonPaths(), session.lastPrepareSeconds());
        }
        // The script (view/script_player.h), while no window input waits: its next commands, up
        // to the first change or wait. (Not in the iteration that finds a preparation done: its
        // first image is shown first.)
        if (!justPrepared && actions.empty()) {
            ScriptState state;
            state.changeShown = stats.lastChangeShown();
            if (shownSamples != UINT32_MAX) state.shownSamples = shownSamples;
            state.targetSamples = session.settings().frame.samplesPerPixel;
            state.refreshDue = session.refreshDue();
            actions = script.advance(state, [&](const ScriptEvent& e) {
                writeScreenshot(e.path, display->linearImage(), options, session);
                if (!render.quiet)
                    fmt::print(stderr, "{}: wrote {} ({})\n", e.where, printable(e.path.string()),
                               session.inPreview() ? std::string("the preview: one path-traced sample")
                                                   : fmt::format("{} spp", shownSamples));
            }, quit);
        }

        // Input: camera and scene changes are gathered, then applied once (one restart).
        std::string sceneKind, viewKind;
        bool resized = false;
        for (const ViewAction& a : actions) {
            switch (a.kind) {
            case ViewAction::Kind::Resize: {
                const uint32_t w = uint32_t(a.a.x), h = uint32_t(a.a.y);
                if (w == width && h == height) break;
                if (window && (window->width() != w || window->height() != h)) window->resize(w, h);  // a script's
                width = w;
                height = h;
                resized = true;
                viewKind = "resize";
                break;
            }
            case ViewAction::Kind::Orbit:
                camera.orbit(a.a.x, a.a.y);
                viewKind = "orbit";
                break;
            case ViewAction::Kind::Pan:
                camera.pan(a.a, a.b, height);
                viewKind = "pan";
                break;
            case ViewAction::Kind::Dolly:
                camera.dolly(a.amount);
                viewKind = "dolly";
                break;
            case ViewAction::Kind::Select:
                selected = pickNode(session.scene(), session.arrays(), session.frame().gpuCamera, width, height, a.a);
                if (!render.quiet)
                    fmt::print(stderr, "{}\n", selected >= 0 ? fmt::format("selected {}", printable(source.nodeName(selected)))
                                                             : std::string("nothing selected"));
                updateMask();
                break;
            case ViewAction::Kind::MoveSelected: {
                glm::vec3 centre;
                if (selected < 0 || !nodeCentre(session.scene(), selected, centre)) break;
                moveNode(selected, glm::dvec3(camera.imagePlaneDelta(centre, a.a, a.b, height)));
                sceneKind = "move";
                break;
            }
            case ViewAction::Kind::MoveNode:
                moveNode(source.findNode(a.node), a.delta);
                sceneKind = "move";
                break;
            case ViewAction::Kind::Key:
                switch (a.key) {
                case ViewKey::Integrator:
                    integratorIndex = (integratorIndex + 1) % integrators.size();
                    session.setIntegrator(*integrators[integratorIndex].second);
                    applyChange("integrator", PhotonRefresh::Full);
                    break;
                case ViewKey::Restart: applyChange("restart", PhotonRefresh::Full); break;
                case ViewKey::Screenshot: {
                    const std::filesystem::path path =
                        std::filesystem::path("out") / fmt::format("{}-view-{:04}.exr", render.scene.stem().string(), screenshots++);
                    if (shownSamples != UINT32_MAX) writeScreenshot(path, display->linearImage(), options, session);
                    if (!render.quiet) fmt::print(stderr, "wrote {}\n", printable(path.string()));
                    break;
                }
                case ViewKey::PlayPause:
                    playing = !playing;
                    animated = true;
                    lastTick = Clock::now();
                    break;
                case ViewKey::Help: fmt::print("{}", viewHelpText()); break;
                case ViewKey::Quit: quit = true; break;
                }
                break;
            }
        }
        if (quit) break;
        if (playing) {
            animationTime += secondsSince(lastTick);
            lastTick = Clock::now();
            if (source.animation().endTime() > source.animation().startTime() && animationTime > source.animation().endTime())
                animationTime = source.animation().startTime();
            if (sceneKind.empty()) sceneKind = "animation";
        }
        if (resized) {  // a new film, display pass and swapchain; the camera keeps its vertical field of view
            session.resize(width, height);
            presenter.resize(width, height);
            display = std::make_unique<DisplayPass>(context, width, height, displayTable);
            redraw = true;
        }
        if (!sceneKind.empty()) {
            const auto at = Clock::now();
            const bool rebuilt = session.setScene(sceneNow());
            if (!viewKind.empty()) session.setView(camera.view(render.frame.view));
            session.restart(rebuilt ? PhotonRefresh::Full : PhotonRefresh::Selective);
            stats.change(sceneKind, at, session.lastPhotonPaths(), session.lastFullPhotonPaths(), session.lastPrepareSeconds(),
                         rebuilt);
            shownSamples = UINT32_MAX;
            restartAt = Clock::now();
            if (selected >= 0) updateMask();
        } else if (!viewKind.empty()) {
            session.setView(camera.view(render.frame.view));
            applyChange(viewKind, PhotonRefresh::Reuse);
        }

        // Samples: one bounded batch per iteration; once the image holding the last change has
        // been shown, the stale photon groups a move left are refreshed round by round (each
        // prepared on its own thread while the window shows the last image).
        uint32_t rendered = 0;
        if (!session.inPreview() && session.refreshDue() && shownSamples != UINT32_MAX) {
            session.refreshRound();
            shownSamples = UINT32_MAX;  // the image on screen is the last round's
            restartAt = Clock::now();
        }
        // A preview is shown before the preparation that follows it starts.
        if (!(session.hasPreviewImage() && shownSamples == UINT32_MAX))
            rendered = session.step(std::max({kFrameSeconds - showSeconds, kRenderPerShow * showSeconds, kMinRenderSeconds}));
        if (session.preparing()) continue;  // the film is the preparation's until it is done
        if (rendered > 0 || session.partRecorded() || shownSamples != session.samples() || redraw) {
            const auto showStart = Clock::now();
            presenter.present(display->pixels(), [&](VkCommandBuffer cmd) {
                display->record(cmd, session.film().sums(), session.progressiveEstimates(), session.samples(),
                               render.display.exposureScale(), presenter.bgra());
            });
            showSeconds = secondsSince(showStart);
            shownSamples = session.samples();
            redraw = false;
            stats.presented(Clock::now(), session.inPreview());
            if (!startup.contains("firstPresentSeconds")) startup["firstPresentSeconds"] = secondsSince(start);
            const double seconds = secondsSince(restartAt);
            setTitle(fmt::format("vkphoton view: {} | {} | {}/{} spp | {:.1f} spp/s | {} photon paths{}{}", sceneName,
                                        session.integratorName(), session.samples(), session.settings().frame.samplesPerPixel,
                                        seconds > 0.0 ? session.samples() / seconds : 0.0, session.lastPhotonPaths(),
                                        stats.changes().empty() ? " (first build)" : " (last change)",
                                        session.refreshDue() ? fmt::format(", refreshing: {} stale photon groups", session.staleGroups())
                                                             : std::string()));
        } else if (!script.waitingForTime()) {
            std::this_thread::sleep_for(std::chrono::duration<double>(kIdleSeconds));  // idle: nothing to render
        }
    }

    if (!render.statsJson.empty()) {
        nlohmann::json json = stats.toJson(Clock::now());
        json["scene"] = render.scene.string();
        json["integrator"] = session.integratorName();
        json["device"] = context.deviceName();
        json["width"] = width;  // at the end (after any resize)
        json["height"] = height;
        json["headless"] = options.headless;
        json["sampleParts"] = session.partsRecorded();
        json["spp"] = render.frame.samplesPerPixel;
        json["preview"] = settings.preview;
        json["startup"] = startup;
        writeTextAtomically(render.statsJson, json.dump(2) + "\n");
    }
    if (!render.quiet && stats.firstImageSeconds())
        fmt::print(stderr, "first image after {:.2f} s; {} change(s), {} frames presented{}\n", *stats.firstImageSeconds(),
                   stats.changes().size(), stats.framesPresented(),
                   stats.presentedPerSecond() ? fmt::format(" ({:.1f} per second)", *stats.presentedPerSecond()) : "");
    if (context.validationEnabled()) context.throwOnValidationMessages();
    return kExitOk;
}

}  // namespace vkp
