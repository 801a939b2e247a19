// `vkphoton render`: the frame, view, environment, output and device options every integrator
// reads, the animation options (--frames and what needs it), and the options of the integrator
// families, each group read only by the kinds it names (render/integrator_registry.h).
#include <map>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/builtin_integrators.h"
#include "app/cli_options.h"
#include "app/commands.h"
#include "app/subcommand.h"
#include "image/exposure.h"
#include "render/crop_window.h"
#include "util/check_range.h"
#include "util/cli_choice.h"
#include "util/errors.h"

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

class RenderCommand : public Subcommand {
public:
    explicit RenderCommand(CLI::App& app);
    const CLI::App& app() const override { return *m_cmd; }
    int run() override;

private:
    void addAnimationOptions();
    void addIntegratorOptions();
    // The kind --integrator and --progressive choose.
    std::string chosenIntegrator() const;

    CLI::App* m_cmd = nullptr;
    RenderCommandOptions m_options;
    bool m_bsdfOnly = false;
    std::string m_aovList;
    std::string m_tileText, m_cropText;  // resolved once --width and --height are known
    std::string m_framesText;            // parsed after CLI11 (animation/frame_sequence.h)
    std::string m_photonUpdate = "selective";
    std::string m_sceneUpdate = "inplace";
    std::string m_photonDetect = "tracks";
    std::string m_exposureText = "auto";  // parsed after CLI11 (image/exposure.h)
    std::string m_integratorName = kDefaultIntegrator;
    bool m_progressive = false;
    std::unique_ptr<IntegratorOptions> m_integratorOptions;
    std::map<std::string, std::unique_ptr<IntegratorConfig>> m_configs;  // by family
};

RenderCommand::RenderCommand(CLI::App& app) {
    m_cmd = app.add_subcommand("render", "Render a glTF scene to OpenEXR (linear) and PNG (tonemapped sRGB)");
    RenderCommandOptions& render = m_options;
    m_cmd->add_option("scene", render.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    m_cmd->add_option("-o,--output", render.output,
                      "Output EXR path; a PNG is written beside it [default: out/SCENE.exr]");
    addFrameOptions(*m_cmd, render.frame, m_bsdfOnly);
    addViewOptions(*m_cmd, render.frame.view);
    addEnvironmentOptions(*m_cmd, render.environment);
    m_cmd->add_option("--aov", m_aovList,
                      "Extra EXR channels, comma-separated: albedo (Albedo.R/G/B), normal (N.X/N.Y/N.Z, world space), "
                      "depth (Z, metres) of the first non-specular surface, for denoisers and compositing")
        ->type_name("LIST");
    addDeviceOptions(*m_cmd, render.device, render.validate, render.maxMemoryGiB, render.textures);
    addSceneIndexOption(*m_cmd, render.sceneIndex);
    m_cmd->add_option("--variant", render.variant,
                      "KHR_materials_variants: render the file's material variant of this name (`vkphoton info` lists "
                      "them) [default: each primitive's own material]")
        ->type_name("NAME");
    m_cmd->add_option("--stats-json", render.statsJson, "Write timings and counters as JSON to this file");
    CLI::Option* tileOption =
        m_cmd->add_option("--tile", m_tileText,
                          "Render only the I-th of N bands of whole rows (1 <= I <= N): a part for `vkphoton merge`, "
                          "with the same pixels as the full render")
            ->type_name("I/N");
    m_cmd->add_option("--crop", m_cropText,
                      "Render only the pixels X0 <= x < X1, Y0 <= y < Y1 (the GPU computes the rows they span): a "
                      "part for `vkphoton merge`")
        ->type_name("X0,Y0,X1,Y1")
        ->excludes(tileOption);
    m_cmd->add_flag("--quiet", render.quiet, "No progress output");
    addAnimationOptions();
    m_cmd->add_flag("--no-energy-compensation", render.noEnergyCompensation,
                    "The glTF spec's plain single-scattering GGX: no multiple-scattering compensation of rough "
                    "specular lobes (docs/materials.md)");
    const auto views = viewTransformChoices();
    m_cmd->add_option("--tonemap", render.display.view,
                      "The PNG's view transform: agx (Blender 4's AgX), aces-fit (Narkowicz's ACES fit), clamp (clip "
                      "to [0, 1]); the EXR stays linear")
        ->transform(oneOf(views))
        ->option_text(choiceText(views, render.display.view));
    m_cmd->add_option("--exposure", m_exposureText,
                      "Exposure of the PNG in stops: the radiance is scaled by 2^EV before the view transform; auto "
                      "meters the image (its trimmed log-average luminance to mid grey 0.18); the EXR stays linear "
                      "and records the EV")
        ->type_name("auto|EV")
        ->capture_default_str();
    render.lightSampling.addOptions(*m_cmd);
    addIntegratorOptions();
}

void RenderCommand::addAnimationOptions() {
    RenderCommandOptions& render = m_options;
    m_cmd->add_option("--frames", m_framesText,
                      "Render the frames FIRST..LAST (inclusive) of the file's glTF animations; -o needs a run of '#' "
                      "for the frame number (out/frame-####.exr) [default -o: out/SCENE-####.exr]")
        ->type_name("FIRST:LAST");
    m_cmd->add_option("--fps", render.fps, "--frames: frames per second (frame f is at f / FPS seconds)")
        ->capture_default_str();
    m_cmd->add_option("--animation", render.animation,
                      "--frames: play only glTF animation N [default: all animations together]")
        ->check(CLI::NonNegativeNumber);
    m_cmd->add_option("--photon-update", m_photonUpdate,
                      "--frames: selective retraces only the photon groups the motion changed (Dmitriev et al. "
                      "2002), full retraces every path each frame")
        ->check(CLI::IsMember({"selective", "full"}))
        ->capture_default_str();
    m_cmd->add_option("--scene-update", m_sceneUpdate,
                      "--frames: inplace moves instances, lights and cameras in the scene built once (rebuilding "
                      "only when other things change), rebuild builds the scene and the kernels every frame")
        ->check(CLI::IsMember({"inplace", "rebuild"}))
        ->capture_default_str();
    m_cmd->add_option("--photon-budget", render.photonBudget,
                      "--frames, selective: photon paths traced per map and frame, pilots included [default: paths / "
                      "8 + one pilot per group]")
        ->check(CLI::PositiveNumber);
    m_cmd->add_option("--photon-groups", render.photonGroups,
                      "--frames, selective: photon groups (path i in group i mod N; keep N a product of powers of 2, "
                      "3, 5, 7, 11)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    m_cmd->add_option("--photon-detect", m_photonDetect,
                      "--frames, selective: how changed photon paths are found: tracks (every path's segments "
                      "against the old and new bounds of what moved, and pilots for the rest) or pilots only")
        ->check(CLI::IsMember({"tracks", "pilots"}))
        ->capture_default_str();
    m_cmd->add_flag("--verify-update", render.verifyUpdate,
                    "--frames, selective: after each update retrace every path in full and count the stored "
                    "photons that differ (stale photons, paths, groups per map in --stats-json)");
}

void RenderCommand::addIntegratorOptions() {
    registerBuiltinIntegrators();
    std::string help = "The integrator:";
    std::string choices;
    for (const IntegratorKind& kind : integratorKinds()) {
        help += fmt::format(" {} ({});", kind.name, kind.summary);
        choices += (choices.empty() ? "" : "|") + kind.name;
    }
    m_cmd->add_option("--integrator", m_integratorName, help)
        ->check(registeredIntegrator())
        ->option_text(fmt::format("{} [{}]", choices, m_integratorName));
    m_cmd->add_flag("--progressive", m_progressive,
                    "Stochastic progressive photon mapping: the same as --integrator sppm (with --integrator photon "
                    "or alone)");
    // One config per family: its options registered once, in groups that name their readers.
    m_integratorOptions = std::make_unique<IntegratorOptions>(*m_cmd);
    for (const IntegratorKind& kind : integratorKinds()) {
        std::unique_ptr<IntegratorConfig>& config = m_configs[kind.familyName()];
        if (config) continue;
        config = kind.makeConfig();
        config->addOptions(*m_integratorOptions);
    }
}

std::string RenderCommand::chosenIntegrator() const {
    if (!m_progressive) return m_integratorName;
    const bool named = m_cmd->get_option("--integrator")->count() > 0;
    if (named && m_integratorName != "photon" && m_integratorName != "sppm")
        throw InputError(fmt::format("--progressive is --integrator sppm: it cannot go with --integrator {}",
                                     m_integratorName));
    return "sppm";
}

int RenderCommand::run() {
    RenderCommandOptions& render = m_options;
    requireNonEmpty(*m_cmd, "--output", render.output);
    requireNonEmpty(*m_cmd, "--stats-json", render.statsJson);
    checkRange("--max-memory", render.maxMemoryGiB, 0.0, 1.0e6);
    render.frame.nextEventEstimation = !m_bsdfOnly;
    if (!m_tileText.empty()) render.frame.crop = parseTile(m_tileText, render.frame.width, render.frame.height);
    if (!m_cropText.empty()) render.frame.crop = parseCrop(m_cropText);
    render.frame.check();
    render.display = parseExposure(m_exposureText, render.display);
    render.environment.check();
    if (m_cmd->get_option("--aov")->count() > 0) render.aov = parseAovList(m_aovList);
    if (m_cmd->get_option("--frames")->count() > 0) render.frames = parseFrameRange(m_framesText);
    render.photonUpdateFull = m_photonUpdate == "full";
    render.sceneRebuildEachFrame = m_sceneUpdate == "rebuild";
    render.photonDetectPilots = m_photonDetect == "pilots";
    if (!render.frames)
        refuseWithout(*m_cmd, {"--photon-update", "--scene-update", "--photon-budget", "--photon-groups", "--fps",
                               "--animation", "--photon-detect", "--verify-update"},
                      "--frames");
    if (render.photonUpdateFull)
        refuseWithout(*m_cmd, {"--photon-detect", "--verify-update", "--photon-budget", "--photon-groups"},
                      "--photon-update selective");
    if (render.frame.direct != DirectLight::Raster) refuseWithout(*m_cmd, {"--area-light-samples"}, "--direct raster");
    render.lightSamplerAuto = m_cmd->get_option("--light-sampler")->count() == 0;
    render.lightSampling.checkGiven(*m_cmd);
    const std::string kind = chosenIntegrator();
    m_integratorOptions->refuseUnread(kind);
    IntegratorConfig& config = *m_configs.at(findIntegrator(kind)->familyName());
    config.choose(kind);
    config.check();
    return runRender(render, config);
}

}  // namespace

std::unique_ptr<Subcommand> addRenderCommand(CLI::App& app) { return std::make_unique<RenderCommand>(app); }

}  // namespace vkp
