// vkphoton command line: `render`, `photons` and `devices`. Exit codes: 0 ok, 1 runtime failure, 2 bad usage
// or bad input.
#include <cctype>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/commands.h"
#include "util/errors.h"

namespace {

// A transform for an option whose value is one of `choices` (case-insensitive), with an error
// that lists them ("--integrator: 'nope' is not one of path, photon, guided").
template <typename T>
CLI::Validator oneOf(const std::vector<std::pair<std::string, T>>& choices) {
    std::string names;
    for (const auto& [name, value] : choices) names += (names.empty() ? "" : ", ") + name;
    return CLI::Validator(
        [choices, names](std::string& input) -> std::string {
            std::string lower = input;
            for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            for (const auto& [name, value] : choices)
                if (name == lower) {
                    input = std::to_string(static_cast<int>(value));
                    return {};
                }
            return "'" + input + "' is not one of " + names;
        },
        "");
}

}  // namespace

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton: a Vulkan compute photon mapper and path tracer"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "vkphoton 0.1.0");

    RenderCommandOptions render;
    RenderSettings& s = render.settings;
    CLI::App* renderCmd = app.add_subcommand("render", "Render a glTF scene to OpenEXR (linear) and PNG (tonemapped sRGB)");
    renderCmd->add_option("scene", render.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    renderCmd->add_option("-o,--output", render.output, "Output EXR path; a PNG is written beside it [default: out/SCENE.exr]");
    renderCmd->add_option("--spp", s.samplesPerPixel, "Samples per pixel")->capture_default_str()->check(CLI::Range(1u, 1u << 24));
    renderCmd->add_option("--width", s.width, "Image width in pixels")->capture_default_str()->check(CLI::Range(1u, 16384u));
    renderCmd->add_option("--height", s.height, "Image height in pixels")->capture_default_str()->check(CLI::Range(1u, 16384u));
    renderCmd->add_option("--seed", s.seed, "Random seed: the same seed gives the same image on the same device")->capture_default_str();
    renderCmd->add_option("--max-depth", s.maxDepth, "Maximum path length (bounces)")->capture_default_str()->check(CLI::Range(1u, 1024u));
    renderCmd->add_option("--time-limit", s.timeLimitSeconds, "Stop after this many seconds (0: no limit); the image is marked partial")->check(CLI::NonNegativeNumber);
    renderCmd->add_option("--camera", s.cameraIndex, "Index of the scene camera to render from [default: first, or a framing of the scene]")->check(CLI::NonNegativeNumber);
    renderCmd->add_option("--device", render.device, "Vulkan device: index or name substring (see `vkphoton devices`)");
    renderCmd->add_flag("--validate", render.validate, "Enable the Khronos validation layer; any message is an error");
    renderCmd->add_option("--stats-json", render.statsJson, "Write timings and counters as JSON to this file");
    renderCmd->add_flag("--quiet", render.quiet, "No progress output");
    bool bsdfOnly = false;
    renderCmd->add_flag("--no-nee", bsdfOnly, "Disable next-event estimation (BSDF sampling only; a reference)");
    renderCmd->add_option("--integrator", s.integrator,
                          "path (path tracing, the reference), photon (photon mapping) or guided (photon-guided path tracing)")
        ->transform(oneOf<Integrator>({{"path", Integrator::Path}, {"photon", Integrator::Photon}, {"guided", Integrator::Guided}}))
        ->option_text("path|photon|guided [path]");
    renderCmd->add_option("--direct", s.direct, "Direct light at the first vertex: traced (next-event estimation, the reference) or raster (stencil shadow volumes)")
        ->transform(oneOf<DirectLight>({{"traced", DirectLight::Traced}, {"raster", DirectLight::Raster}}))
        ->option_text("traced|raster [traced]");
    renderCmd->add_option("--area-light-samples", s.areaLightSamples, "--direct raster: point samples per emissive triangle (0: emissive triangles stay traced)")
        ->capture_default_str()->check(CLI::Range(0u, 4096u));
    PhotonRenderSettings& ph = s.photon;
    CLI::Option_group* photonGroup = renderCmd->add_option_group("photon integrator");
    photonGroup->add_option("--photons", ph.globalPaths, "Photon paths for the global map (per pass with --progressive)")->capture_default_str()->check(CLI::Range(1u, 1u << 26));
    CLI::Option* causticOption = photonGroup->add_option("--caustic-photons", ph.causticPaths, "Photon paths for the caustic map (0: no caustic map)")->capture_default_str()->check(CLI::Range(0u, 1u << 26));
    photonGroup->add_option("--gather-rays", ph.gatherRays, "Final gather rays per sample (0: read the global map at the visible point)")->capture_default_str()->check(CLI::Range(0u, 1024u));
    photonGroup->add_option("--gather-k", ph.gatherK, "Nearest photons per global-map estimate")->capture_default_str()->check(CLI::Range(1u, 64u));
    photonGroup->add_option("--radiance-photons", ph.radiancePhotonStride, "Every n-th global photon carries a precomputed irradiance estimate that final gathers read (0: a k-nearest estimate at every gather hit)")->capture_default_str()->check(CLI::Range(0u, 1024u));
    photonGroup->add_option("--radius", ph.radius, "Caustic gather radius and initial progressive radius, world units [default: 1.5% of the scene's bounding radius]")->check(CLI::PositiveNumber);
    photonGroup->add_flag("--progressive", ph.progressive, "Stochastic progressive photon mapping: a fresh photon pass per sample, shrinking radii (converges to the path tracer)");
    photonGroup->add_option("--alpha", ph.alpha, "Progressive radius reduction: fraction of new photons kept per pass")->capture_default_str()->check(CLI::Range(0.01f, 0.99f));
    photonGroup->add_option("--deposit", ph.deposit, "Which photons the maps keep: all; importance (kept with a probability from the camera's importance, Keller & Wald); density (kept until a required density is met, Suykens & Willems)")
        ->transform(oneOf<DepositMode>({{"all", DepositMode::All}, {"importance", DepositMode::Importance}, {"density", DepositMode::Density}}))
        ->option_text("all|importance|density [importance]");
    CLI::Option* qOption = photonGroup->add_option("--q", ph.q, "Keller & Wald's ratio: --photons paths fill the caustic map and the first q of them the global map (instead of --caustic-photons)")->check(CLI::Range(1e-6f, 1.0f));
    qOption->excludes(causticOption);
    photonGroup->add_option("--importons", ph.importonPaths, "Camera paths of the importon pass (--deposit importance|density)")->capture_default_str()->check(CLI::Range(1u, 1u << 24));
    photonGroup->add_option("--deposit-epsilon", ph.depositEpsilon, "Least acceptance probability of a photon (its power grows at most 1/epsilon times)")->capture_default_str()->check(CLI::Range(1e-6f, 1.0f));
    photonGroup->add_flag("--deposit-cutoff", ph.depositCutoff, "Drop photons whose acceptance is below --deposit-epsilon instead of clamping it (biased, fewer photons)");
    photonGroup->add_option("--density-accuracy", ph.densityAccuracy, "--deposit density: required photons per square unit per unit of path importance")->capture_default_str()->check(CLI::PositiveNumber);
    photonGroup->add_option("--density-rounds", ph.densityRounds, "--deposit density: rounds of tracing, deciding and rebuilding the grid")->capture_default_str()->check(CLI::Range(1u, 256u));
    photonGroup->add_flag("--density-roulette", ph.densityRoulette, "--deposit density: keep photons with Russian-roulette weights instead of handing rejected power to the stored neighbours");

    GuideRenderSettings& gd = s.guide;
    CLI::Option_group* guideGroup = renderCmd->add_option_group("guided path tracer");
    guideGroup->add_option("--guide-photons", gd.photons, "Photon paths for the guiding map")->capture_default_str()->check(CLI::Range(1u, 1u << 26));
    guideGroup->add_option("--guide-k", gd.k, "Nearest photons per guiding grid")->capture_default_str()->check(CLI::Range(1u, 64u));
    std::string guideGrid = "4x16";
    guideGroup->add_option("--guide-grid", guideGrid, "Guiding grid MxN over the unit square (theta bands x phi sectors, M*N <= 64)")->capture_default_str()
        ->check([](const std::string& v) -> std::string {
            unsigned m = 0, n = 0;
            char x = 0, extra = 0;
            if (std::sscanf(v.c_str(), "%u%c%u%c", &m, &x, &n, &extra) != 3 || x != 'x' || m == 0 || n == 0 || m * n > 64)
                return "expected MxN with M*N between 1 and 64, e.g. 4x16";
            return {};
        });
    guideGroup->add_option("--guide-cache", gd.cache, "on: grids built once per cache cell and normal bin; off: a k-nearest gather at every vertex (the paper)")
        ->transform(oneOf<bool>({{"on", true}, {"off", false}}))->option_text("on|off [on]");
    guideGroup->add_option("--guide-adapt", gd.adaptPhotons, "Coarsen a guiding-cache grid whose photons are too few, down to this many photons per direction cell (0: every grid at --guide-grid)")->capture_default_str()->check(CLI::Range(0u, 65535u));
    guideGroup->add_option("--guide-rr", gd.roulette, "on: Russian roulette by the guide's estimate of the light a path still brings against the pixel's (adjoint-driven); off: by the path's throughput")
        ->transform(oneOf<bool>({{"on", true}, {"off", false}}))->option_text(gd.roulette ? "on|off [on]" : "on|off [off]");
    guideGroup->add_option("--guide-mix", gd.mix, "Probability of sampling the guiding grid rather than the BSDF (1: the paper's method)")->capture_default_str()->check(CLI::Range(0.0f, 1.0f));

    PhotonsCommandOptions photons;
    CLI::App* photonsCmd = app.add_subcommand("photons", "Trace photons and write the photon maps as a PLY point cloud");
    photonsCmd->add_option("scene", photons.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    photonsCmd->add_option("-o,--output", photons.output, "Output .ply [default: out/SCENE-photons.ply]");
    photonsCmd->add_option("--photons", photons.photons, "Photon paths to emit")->capture_default_str()->check(CLI::Range(1u, 1u << 26));
    photonsCmd->add_option("--max-deposits", photons.maxDeposits, "Stored photons per path at most")->capture_default_str()->check(CLI::Range(1u, 64u));
    photonsCmd->add_option("--seed", photons.seed, "Random seed")->capture_default_str();
    photonsCmd->add_option("--deposit", photons.deposit.deposit, "Which photons the map keeps: all, importance or density (as for render)")
        ->transform(oneOf<DepositMode>({{"all", DepositMode::All}, {"importance", DepositMode::Importance}, {"density", DepositMode::Density}}))
        ->option_text("all|importance|density [all]");
    photonsCmd->add_option("--importons", photons.deposit.importonPaths, "Camera paths of the importon pass")->capture_default_str()->check(CLI::Range(1u, 1u << 24));
    photonsCmd->add_option("--deposit-epsilon", photons.deposit.depositEpsilon, "Least acceptance probability of a photon")->capture_default_str()->check(CLI::Range(1e-6f, 1.0f));
    photonsCmd->add_flag("--deposit-cutoff", photons.deposit.depositCutoff, "Drop photons below --deposit-epsilon (biased)");
    photonsCmd->add_option("--density-accuracy", photons.deposit.densityAccuracy, "--deposit density: required photons per square unit per unit of path importance")->capture_default_str()->check(CLI::PositiveNumber);
    photonsCmd->add_option("--width", photons.width, "Width of the image the importons' camera looks at")->capture_default_str()->check(CLI::Range(1u, 16384u));
    photonsCmd->add_option("--height", photons.height, "Height of that image")->capture_default_str()->check(CLI::Range(1u, 16384u));
    photonsCmd->add_option("--camera", photons.cameraIndex, "Scene camera index for the importons")->check(CLI::NonNegativeNumber);
    photonsCmd->add_option("--device", photons.device, "Vulkan device: index or name substring");
    photonsCmd->add_flag("--validate", photons.validate, "Enable the Khronos validation layer; any message is an error");
    photonsCmd->add_flag("--quiet", photons.quiet, "No summary output");

    GuideGridCommandOptions guideGridOptions;
    CLI::App* guideCmd = app.add_subcommand("guide-grid", "Write the guided path tracer's direction grid at one pixel as a PNG");
    guideCmd->add_option("scene", guideGridOptions.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    guideCmd->add_option("--pixel", [&](const CLI::results_t& r) {
        guideGridOptions.x = static_cast<uint32_t>(std::stoul(r.at(0)));
        guideGridOptions.y = static_cast<uint32_t>(std::stoul(r.at(1)));
        return true;
    }, "Pixel X Y (from the top left)")->expected(2)->required()->check(CLI::NonNegativeNumber);
    guideCmd->add_option("-o,--output", guideGridOptions.output, "Output .png [default: out/SCENE-guide-X-Y.png]");
    guideCmd->add_option("--width", guideGridOptions.width, "Image width the pixel belongs to")->capture_default_str()->check(CLI::Range(1u, 16384u));
    guideCmd->add_option("--height", guideGridOptions.height, "Image height the pixel belongs to")->capture_default_str()->check(CLI::Range(1u, 16384u));
    guideCmd->add_option("--camera", guideGridOptions.cameraIndex, "Scene camera index")->check(CLI::NonNegativeNumber);
    guideCmd->add_option("--seed", guideGridOptions.seed, "Random seed")->capture_default_str();
    guideCmd->add_option("--guide-photons", guideGridOptions.guide.photons, "Photon paths for the guiding map")->capture_default_str()->check(CLI::Range(1u, 1u << 26));
    guideCmd->add_option("--guide-k", guideGridOptions.guide.k, "Nearest photons in the grid")->capture_default_str()->check(CLI::Range(1u, 64u));
    std::string debugGrid = "4x16";
    guideCmd->add_option("--guide-grid", debugGrid, "Grid MxN (M*N <= 64)")->capture_default_str();
    guideCmd->add_option("--device", guideGridOptions.device, "Vulkan device: index or name substring");
    guideCmd->add_flag("--validate", guideGridOptions.validate, "Enable the Khronos validation layer");
    guideCmd->add_flag("--quiet", guideGridOptions.quiet, "No output but the file");

    app.add_subcommand("devices", "List the Vulkan devices");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExitOk : kExitBadInput;
    }
    s.nextEventEstimation = !bsdfOnly;
    if (renderCmd->parsed()) std::sscanf(guideGrid.c_str(), "%ux%u", &gd.gridU, &gd.gridV);
    if (guideCmd->parsed() && std::sscanf(debugGrid.c_str(), "%ux%u", &guideGridOptions.guide.gridU,
                                          &guideGridOptions.guide.gridV) != 2) {
        fmt::print(stderr, "error: --guide-grid {}: expected MxN, e.g. 4x16\n", debugGrid);
        return kExitBadInput;
    }

    try {
        if (renderCmd->parsed()) return runRender(render);
        if (photonsCmd->parsed()) return runPhotons(photons);
        if (guideCmd->parsed()) return runGuideGrid(guideGridOptions);
        return runDevices();
    } catch (const InputError& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return kExitRuntimeFailure;
    }
}
