#include "app/cli.h"

#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/compare_command.h"
#include "app/commands.h"
#include "app/info_command.h"
#include "app/merge_command.h"
#include "image/exposure.h"
#include "render/crop_window.h"
#include "util/cli_choice.h"
#include "util/check_range.h"
#include "util/errors.h"
#include "util/printable.h"

namespace vkp {
namespace {

// --integrator: one of the registered kinds, named in the error otherwise.
CLI::Validator registeredIntegrator() {
    return CLI::Validator(
        [](std::string& input) -> std::string {
            if (findIntegrator(input)) return {};
            std::string names;
            for (const IntegratorKind& kind : integratorKinds()) names += (names.empty() ? "" : ", ") + kind.name;
            return "'" + input + "' is not one of " + names;
        },
        "");
}

void addFrameOptions(CLI::App& cmd, FrameSettings& frame, bool& bsdfOnly) {
    cmd.add_option("--spp", frame.samplesPerPixel, "Samples per pixel")->capture_default_str();
    cmd.add_option("--width", frame.width, "Image width in pixels")->capture_default_str();
    cmd.add_option("--height", frame.height, "Image height in pixels")->capture_default_str();
    cmd.add_option("--seed", frame.seed, "Random seed: the same seed gives the same image on the same device")
        ->capture_default_str();
    cmd.add_option("--max-depth", frame.maxDepth, "Maximum path length (bounces)")->capture_default_str();
    cmd.add_option("--time-limit", frame.timeLimitSeconds,
                   "Stop after this many seconds (0: no limit); the image is marked partial");
    cmd.add_option("--camera", frame.cameraIndex,
                   "Index of the scene camera to render from [default: first, or a framing of the scene]")
        ->check(CLI::NonNegativeNumber);
    cmd.add_flag("--no-nee", bsdfOnly, "Disable next-event estimation (BSDF sampling only; a reference)");
    const std::vector<std::pair<std::string, DirectLight>> direct{{"traced", DirectLight::Traced},
                                                                  {"raster", DirectLight::Raster}};
    cmd.add_option("--direct", frame.direct,
                   "Direct light at the first vertex: traced (next-event estimation, the reference) or raster "
                   "(stencil shadow volumes)")
        ->transform(oneOf(direct))
        ->option_text(choiceText(direct, frame.direct));
    cmd.add_option("--area-light-samples", frame.areaLightSamples,
                   "--direct raster: point samples per emissive triangle (0: emissive triangles stay traced)")
        ->capture_default_str();
}

// "X,Y,Z": three comma-separated numbers (finite or not: ViewOverride::check names the flag).
std::optional<glm::vec3> parsePoint(const std::string& text) {
    glm::vec3 p;
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const size_t end = k < 2 ? text.find(',', start) : text.size();
        if (end == std::string::npos) return std::nullopt;
        const std::string part = text.substr(start, end - start);
        size_t used = 0;
        try {
            p[k] = std::stof(part, &used);
        } catch (const std::exception&) {
            return std::nullopt;
        }
        if (used != part.size()) return std::nullopt;
        start = end + 1;
    }
    return p;
}

// --look-from, --look-at, --fov, for every command that resolves a camera.
void addViewOptions(CLI::App& cmd, ViewOverride& view) {
    const CLI::Validator point(
        [](std::string& input) -> std::string {
            return parsePoint(input) ? "" : "'" + input + "' is not three numbers X,Y,Z";
        },
        "");
    cmd.add_option_function<std::string>(
           "--look-from", [&view](const std::string& text) { view.lookFrom = parsePoint(text); },
           "Camera position X,Y,Z (world units): overrides the camera's; it looks at --look-at, else at the scene's centre")
        ->check(point)
        ->type_name("X,Y,Z");
    cmd.add_option_function<std::string>(
           "--look-at", [&view](const std::string& text) { view.lookAt = parsePoint(text); },
           "Point X,Y,Z the camera looks at (world units), from --look-from or where the camera stands")
        ->check(point)
        ->type_name("X,Y,Z");
    cmd.add_option_function<float>("--fov", [&view](float degrees) { view.fovDegrees = degrees; },
                                   "Vertical field of view in degrees, 0 < DEG < 180 [default: the camera's; 40 for the "
                                   "default framing]")
        ->type_name("DEG");
}

// --env, --env-strength, --env-rotation (scene/environment.h, docs/environment.md).
void addEnvironmentOptions(CLI::App& cmd, EnvironmentSettings& env) {
    cmd.add_option("--env", env.value,
                   "Environment light: an equirectangular .hdr or .exr map, or a radiance V or R,G,B (0: none) "
                   "[default: none, or radiance 1 for a scene without lights]")
        ->type_name("FILE|VALUE");
    cmd.add_option("--env-strength", env.strength, "Multiplies the environment's radiance")->capture_default_str();
    cmd.add_option("--env-rotation", env.rotationDegrees,
                   "Turns the environment map about +Y by DEG (right-handed: at 90 what faced +X faces -Z)")
        ->type_name("DEG")
        ->capture_default_str();
    const std::vector<std::pair<std::string, bool>> sampling{{"map", true}, {"uniform", false}};
    cmd.add_option("--env-sampling", env.importanceSampling,
                   "Next-event directions towards a map: map (its luminance x sin(theta) distribution) or uniform "
                   "(over the sphere; a baseline)")
        ->transform(oneOf(sampling))
        ->option_text(choiceText(sampling, env.importanceSampling));
}

void addDeviceOptions(CLI::App& cmd, std::string& device, bool& validate, double& maxMemoryGiB,
                      TextureOptions& textures) {
    cmd.add_option("--device", device, "Vulkan device: index or name substring (see `vkphoton devices`)");
    cmd.add_flag("--validate", validate, "Enable the Khronos validation layer; any message is an error");
    cmd.add_option("--max-memory", maxMemoryGiB,
                   "Memory the scene may take, in GiB, estimated from its triangle count before loading "
                   "(0: the memory available)")
        ->capture_default_str();
    cmd.add_option("--max-texture-size", textures.maxSize,
                   "Largest texture width/height in texels: larger textures are halved (box filter) until they "
                   "fit, with a warning (0: no limit; textures the device cannot hold are always downscaled)")
        ->check(CLI::Range(0u, 1u << 16))
        ->capture_default_str();
    cmd.add_flag("--mipmaps,!--no-mipmaps", textures.mipmaps,
                 "Filter minified textures over what each camera sample covers (mipmaps chosen by ray cones, "
                 "as the samplers' minFilter says; the default), or read full-resolution texels only "
                 "(--no-mipmaps: noisier at few samples, the supersampled reference at many)");
}

// --scene N: which of the file's glTF scenes to load.
void addSceneIndexOption(CLI::App& cmd, int& sceneIndex) {
    cmd.add_option("--scene", sceneIndex, "Index of the glTF scene to load [default: the file's `scene`, else 0]")
        ->check(CLI::NonNegativeNumber);
}

// An option given an empty value (`--q ''`) is a mistake: CLI11 would leave the default.
void refuseEmptyValues(CLI::App& app) {
    for (const CLI::Option* option : app.get_options())
        for (const std::string& value : option->results())
            if (value.empty() && option->get_expected_min() > 0)
                throw InputError(fmt::format("{} '': the value is empty", option->get_name()));
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) refuseEmptyValues(*sub);
}

// A path option that was given must not be empty: `-o ''` is a mistake, not "the default".
void requireNonEmpty(const CLI::App& cmd, const char* name, const std::filesystem::path& value) {
    if (cmd.get_option(name)->count() > 0 && value.empty())
        throw InputError(fmt::format("{} '': the path is empty", name));
}

}  // namespace

int runCommandLine(int argc, const char* const* argv) {
    CLI::App app{"vkphoton: a Vulkan compute photon mapper and path tracer"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "vkphoton 0.1.0");

    RenderCommandOptions render;
    bool bsdfOnly = false;
    std::string integratorName = integratorKinds().front().name;
    CLI::App* renderCmd =
        app.add_subcommand("render", "Render a glTF scene to OpenEXR (linear) and PNG (tonemapped sRGB)");
    renderCmd->add_option("scene", render.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    renderCmd->add_option("-o,--output", render.output,
                          "Output EXR path; a PNG is written beside it [default: out/SCENE.exr]");
    addFrameOptions(*renderCmd, render.frame, bsdfOnly);
    addViewOptions(*renderCmd, render.frame.view);
    addEnvironmentOptions(*renderCmd, render.environment);
    std::string aovList;
    renderCmd
        ->add_option(
            "--aov", aovList,
            "Extra EXR channels, comma-separated: albedo (Albedo.R/G/B), normal (N.X/N.Y/N.Z, world space), depth "
            "(Z, metres) of the first non-specular surface, for denoisers and compositing")
        ->type_name("LIST");
    addDeviceOptions(*renderCmd, render.device, render.validate, render.maxMemoryGiB, render.textures);
    addSceneIndexOption(*renderCmd, render.sceneIndex);
    renderCmd->add_option("--variant", render.variant,
                          "KHR_materials_variants: render the file's material variant of this name (`vkphoton info` "
                          "lists them) [default: each primitive's own material]")
        ->type_name("NAME");
    renderCmd->add_option("--stats-json", render.statsJson, "Write timings and counters as JSON to this file");
    std::string tileText, cropText;  // resolved once --width and --height are known
    CLI::Option* tileOption = renderCmd->add_option(
        "--tile", tileText,
        "Render only the I-th of N bands of whole rows (1 <= I <= N): a part for `vkphoton merge`, with the same "
        "pixels as the full render")->type_name("I/N");
    renderCmd->add_option("--crop", cropText,
                          "Render only the pixels X0 <= x < X1, Y0 <= y < Y1 (the GPU computes the rows they span): "
                          "a part for `vkphoton merge`")
        ->type_name("X0,Y0,X1,Y1")
        ->excludes(tileOption);
    renderCmd->add_flag("--quiet", render.quiet, "No progress output");
    std::string framesText;  // parsed after CLI11 (render/frame_sequence.h)
    renderCmd->add_option("--frames", framesText,
                          "Render the frames FIRST..LAST (inclusive) of the file's glTF animations; -o needs a run of "
                          "'#' for the frame number (out/frame-####.exr) [default -o: out/SCENE-####.exr]")
        ->type_name("FIRST:LAST");
    renderCmd->add_option("--fps", render.fps, "--frames: frames per second (frame f is at f / FPS seconds)")
        ->capture_default_str();
    renderCmd->add_option("--animation", render.animation,
                          "--frames: play only glTF animation N [default: all animations together]")
        ->check(CLI::NonNegativeNumber);
    std::string photonUpdate = "selective";
    renderCmd->add_option("--photon-update", photonUpdate,
                          "--frames: selective retraces only the photon groups the motion changed (Dmitriev et al. "
                          "2002), full retraces every path each frame")
        ->check(CLI::IsMember({"selective", "full"}))
        ->capture_default_str();
    std::string sceneUpdate = "inplace";
    renderCmd->add_option("--scene-update", sceneUpdate,
                          "--frames: inplace moves instances, lights and cameras in the scene built once (rebuilding "
                          "only when other things change), rebuild builds the scene and the kernels every frame")
        ->check(CLI::IsMember({"inplace", "rebuild"}))
        ->capture_default_str();
    renderCmd->add_option("--photon-budget", render.photonBudget,
                          "--frames, selective: photon paths traced per map and frame, pilots included [default: "
                          "paths / 8 + one pilot per group]")
        ->check(CLI::PositiveNumber);
    renderCmd->add_option("--photon-groups", render.photonGroups,
                          "--frames, selective: photon groups (path i in group i mod N; keep N a product of powers "
                          "of 2, 3, 5, 7, 11)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    renderCmd->add_flag("--no-energy-compensation", render.noEnergyCompensation,
                        "The glTF spec's plain single-scattering GGX: no multiple-scattering compensation of rough "
                        "specular lobes (docs/materials.md)");
    const auto views = viewTransformChoices();
    renderCmd->add_option("--tonemap", render.display.view,
                          "The PNG's view transform: agx (Blender 4's AgX), aces-fit (Narkowicz's ACES fit), clamp "
                          "(clip to [0, 1]); the EXR stays linear")
        ->transform(oneOf(views))
        ->option_text(choiceText(views, render.display.view));
    std::string exposureText = "auto";  // parsed after CLI11 (image/exposure.h)
    renderCmd->add_option("--exposure", exposureText,
                          "Exposure of the PNG in stops: the radiance is scaled by 2^EV before the view transform; "
                          "auto meters the image (its trimmed log-average luminance to mid grey 0.18); the EXR "
                          "stays linear and records the EV")
        ->type_name("auto|EV")
        ->capture_default_str();
    const std::vector<std::pair<std::string, LightSampler>> lightSamplers{{"power", LightSampler::Power},
                                                                          {"bvh", LightSampler::Bvh},
                                                                          {"photon", LightSampler::Photon}};
    renderCmd->add_option("--light-sampler", render.lightSampling.sampler,
                          "How next-event estimation chooses a light: power (in proportion to emitted power) or "
                          "bvh (a light BVH by importance at the shading point, Conty Estevez & Kulla 2018) or photon (per "
                          "cell, the lights whose primary photons arrive there, Keller & Wald 2000, mixed with bvh); "
                          "default: bvh for scenes with more than 16 lights (emissive triangles count one each), "
                          "else power")
        ->transform(oneOf(lightSamplers))
        ->option_text("power|bvh|photon [auto]");
    const std::vector<std::pair<std::string, TriangleSampling>> triangleSamplings{
        {"solid-angle", TriangleSampling::SolidAngle}, {"area", TriangleSampling::Area}};
    renderCmd->add_option("--triangle-sampling", render.lightSampling.triangles,
                          "How next-event estimation samples an emissive triangle: solid-angle (uniform over the "
                          "solid angle it subtends, Arvo 1995; by area where that is tiny) or area (by area only)")
        ->transform(oneOf(triangleSamplings))
        ->option_text(choiceText(triangleSamplings, render.lightSampling.triangles));
    renderCmd->add_option("--light-photons", render.lightSampling.cellPhotons,
                          "--light-sampler photon: photon paths whose primary hits fill the light cells")
        ->capture_default_str();
    renderCmd->add_option("--light-cell-k", render.lightSampling.cellK,
                          "--light-sampler photon: candidate lights per cell at most")
        ->capture_default_str();
    renderCmd->add_option("--light-cell-floor", render.lightSampling.cellFloor,
                          "--light-sampler photon: probability of choosing by the light BVH instead of the cell "
                          "(> 0 keeps the estimate unbiased)")
        ->capture_default_str();
    renderCmd->add_option("--light-cell-size", render.lightSampling.cellSize,
                          "--light-sampler photon: cell size in metres (0: the scene's largest extent / 40)")
        ->capture_default_str();
    std::string integratorHelp = "The integrator:";
    std::string integratorChoices;
    for (const IntegratorKind& kind : integratorKinds()) {
        integratorHelp += fmt::format(" {} ({});", kind.name, kind.summary);
        integratorChoices += (integratorChoices.empty() ? "" : "|") + kind.name;
    }
    renderCmd->add_option("--integrator", integratorName, integratorHelp)
        ->check(registeredIntegrator())
        ->option_text(fmt::format("{} [{}]", integratorChoices, integratorName));
    // Every integrator registers its own option group; only the chosen one's values are used.
    std::map<std::string, std::unique_ptr<IntegratorConfig>> configs;
    for (const IntegratorKind& kind : integratorKinds()) {
        configs[kind.name] = kind.makeConfig();
        configs[kind.name]->addOptions(*renderCmd);
    }

    PhotonsCommandOptions photons;
    CLI::App* photonsCmd = app.add_subcommand("photons", "Trace photons and write the photon maps as a PLY point cloud");
    photonsCmd->add_option("scene", photons.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    photonsCmd->add_option("-o,--output", photons.output, "Output .ply [default: out/SCENE-photons.ply]");
    photonsCmd->add_option("--photons", photons.photons, "Photon paths to emit")->capture_default_str();
    photonsCmd->add_option("--max-deposits", photons.maxDeposits,
                           "Photon slots per path: a path with more deposits keeps a uniform random sample of them, "
                           "each weighted up")->capture_default_str();
    photonsCmd->add_option("--seed", photons.seed, "Random seed")->capture_default_str();
    photons.deposit.addOptions(*photonsCmd);
    photonsCmd->add_option("--width", photons.width, "Width of the image the importons' camera looks at")
        ->capture_default_str();
    photonsCmd->add_option("--height", photons.height, "Height of that image")->capture_default_str();
    photonsCmd->add_option("--camera", photons.cameraIndex, "Scene camera index for the importons")->check(CLI::NonNegativeNumber);
    addViewOptions(*photonsCmd, photons.view);
    addEnvironmentOptions(*photonsCmd, photons.environment);
    addDeviceOptions(*photonsCmd, photons.device, photons.validate, photons.maxMemoryGiB, photons.textures);
    addSceneIndexOption(*photonsCmd, photons.sceneIndex);
    photonsCmd->add_flag("--quiet", photons.quiet, "No summary output");

    GuideGridCommandOptions guideGrid;
    CLI::App* guideCmd =
        app.add_subcommand("guide-grid", "Write the guided path tracer's direction grid at one pixel as a PNG");
    guideCmd->add_option("scene", guideGrid.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    std::vector<uint32_t> pixel;
    guideCmd->add_option("--pixel", pixel, "Pixel X Y (from the top left)")->expected(2)->required();
    guideCmd->add_option("-o,--output", guideGrid.output, "Output .png [default: out/SCENE-guide-X-Y.png]");
    guideCmd->add_option("--width", guideGrid.width, "Image width the pixel belongs to")->capture_default_str();
    guideCmd->add_option("--height", guideGrid.height, "Image height the pixel belongs to")->capture_default_str();
    guideCmd->add_option("--camera", guideGrid.cameraIndex, "Scene camera index")->check(CLI::NonNegativeNumber);
    addViewOptions(*guideCmd, guideGrid.view);
    addEnvironmentOptions(*guideCmd, guideGrid.environment);
    guideCmd->add_option("--seed", guideGrid.seed, "Random seed")->capture_default_str();
    guideGrid.guide.addOptions(*guideCmd, false);
    addDeviceOptions(*guideCmd, guideGrid.device, guideGrid.validate, guideGrid.maxMemoryGiB, guideGrid.textures);
    addSceneIndexOption(*guideCmd, guideGrid.sceneIndex);
    guideCmd->add_flag("--quiet", guideGrid.quiet, "No output but the file");

    InfoCommandOptions info;
    CLI::App* infoCmd = app.add_subcommand(
        "info", "Describe a glTF scene: geometry, materials, lights, cameras, animations, extensions, textures");
    infoCmd->add_option("scene", info.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    infoCmd->add_flag("--json", info.json, "Print the report as JSON");
    addSceneIndexOption(*infoCmd, info.sceneIndex);

    app.add_subcommand("devices", "List the Vulkan devices");

    MergeCommandOptions merge;
    CLI::App* mergeCmd = app.add_subcommand(
        "merge", "Join the parts of one render (render --tile or --crop) into the full EXR and PNG, bit for bit");
    mergeCmd->add_option("parts", merge.parts, "The parts' EXR files")->required();
    mergeCmd->add_option("-o,--output", merge.output, "Output EXR path; a PNG is written beside it")->required();
    mergeCmd->add_flag("--quiet", merge.quiet, "No summary output");

    CompareCommandOptions compare;
    CLI::App* compareCmd = app.add_subcommand(
        "compare", "Are two EXRs' pixels identical, bit for bit (every channel)? Exit 0 if so, 3 if not");
    compareCmd->add_option("a", compare.a, "First EXR")->required();
    compareCmd->add_option("b", compare.b, "Second EXR")->required();
    compareCmd->add_flag("--quiet", compare.quiet, "No output, only the exit code");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::ParseError& e) {
        // CLI11 quotes the arguments: escape them (a value may hold terminal escapes).
        if (e.get_exit_code() == 0) return kExitOk;
        fmt::print(stderr, "error: {}\nRun with --help for more information.\n", printable(e.what()));
        return kExitBadInput;
    }

    try {
        refuseEmptyValues(app);
        if (renderCmd->parsed()) {
            requireNonEmpty(*renderCmd, "--output", render.output);
            requireNonEmpty(*renderCmd, "--stats-json", render.statsJson);
            checkRange("--max-memory", render.maxMemoryGiB, 0.0, 1.0e6);
            render.frame.nextEventEstimation = !bsdfOnly;
            if (!tileText.empty()) render.frame.crop = parseTile(tileText, render.frame.width, render.frame.height);
            if (!cropText.empty()) render.frame.crop = parseCrop(cropText);
            render.frame.check();
            render.display = parseExposure(exposureText, render.display);
            render.environment.check();
            if (renderCmd->get_option("--aov")->count() > 0) render.aov = parseAovList(aovList);
            if (renderCmd->get_option("--frames")->count() > 0) render.frames = parseFrameRange(framesText);
            render.photonUpdateFull = photonUpdate == "full";
            render.sceneRebuildEachFrame = sceneUpdate == "rebuild";
            if (!render.frames && (renderCmd->get_option("--photon-update")->count() > 0 ||
                                   renderCmd->get_option("--scene-update")->count() > 0 ||
                                   renderCmd->get_option("--photon-budget")->count() > 0 ||
                                   renderCmd->get_option("--photon-groups")->count() > 0))
                throw InputError("--photon-update, --scene-update, --photon-budget and --photon-groups need --frames");
            if (!render.frames &&
                (renderCmd->get_option("--fps")->count() > 0 || renderCmd->get_option("--animation")->count() > 0))
                throw InputError("--fps and --animation need --frames");
            const IntegratorConfig& config = *configs.at(integratorName);
            config.check();
            render.lightSamplerAuto = renderCmd->get_option("--light-sampler")->count() == 0;
            return runRender(render, config);
        }
        if (photonsCmd->parsed()) {
            requireNonEmpty(*photonsCmd, "--output", photons.output);
            photons.check();
            return runPhotons(photons);
        }
        if (guideCmd->parsed()) {
            requireNonEmpty(*guideCmd, "--output", guideGrid.output);
            guideGrid.x = pixel.at(0);
            guideGrid.y = pixel.at(1);
            guideGrid.check();
            return runGuideGrid(guideGrid);
        }
        if (infoCmd->parsed()) return runInfo(info);
        if (mergeCmd->parsed()) {
            requireNonEmpty(*mergeCmd, "--output", merge.output);
            return runMerge(merge);
        }
        if (compareCmd->parsed()) return runCompare(compare);
        return runDevices();
    } catch (const InputError& e) {
        fmt::print(stderr, "error: {}\n", printable(e.what()));
        return kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", printable(e.what()));
        return kExitRuntimeFailure;
    }
}

}  // namespace vkp
