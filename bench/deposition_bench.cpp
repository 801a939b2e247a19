// Deposition benchmark: stored photons and memory at equal image error, and image
// error at equal stored photons, for --deposit all, importance and density. Usage:
//   build/bench/deposition_bench [SCENE] [--width W --height H --spp N --paths a,b,c
//                                 --deposit-paths a,b,c --reference-paths N --reference FILE.exr
//                                 --modes all,importance,density --density-accuracy C
//                                 --deposit-epsilon E --deposit-cutoff --device D]
// Every render uses the same seed, so the camera samples, next-event estimates and final-gather
// rays are the same in all of them: the difference between two renders is the photon maps'
// alone. The error is the relMSE against a render of the same samples with every photon of
// --reference-paths paths kept. Prints Markdown for docs/benchmarks.md.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <filesystem>
#include <stdexcept>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "image/exr.h"
#include "image/metrics.h"
#include "photon/photon_integrator.h"
#include "render/renderer.h"
#include "shared/photon.glsl"
#include "scene/gltf_loader.h"
#include "vk/context.h"

namespace {

using namespace vkp;

struct Point {
    uint32_t paths = 0;
    uint64_t stored = 0;  // global + caustic photons
    uint64_t bytes = 0;
    double relMse = 0.0;
    double seconds = 0.0;
};

FrameSettings frameFor(uint32_t width, uint32_t height, uint32_t spp) {
    FrameSettings s;
    s.width = width;
    s.height = height;
    s.samplesPerPixel = spp;
    s.seed = 1;
    return s;
}

PhotonIntegratorSettings photonsFor(DepositMode mode, uint32_t paths) {
    PhotonIntegratorSettings p;
    p.deposit.mode = mode;
    p.globalPaths = paths;
    p.causticPaths = 0;  // the scenes have no specular surfaces
    return p;
}

// log-log interpolation of y at x over points sorted by x (clamped to the ends: -1 outside).
double interpolate(const std::vector<std::pair<double, double>>& xy, double x) {
    for (size_t i = 1; i < xy.size(); ++i) {
        const auto [x0, y0] = xy[i - 1];
        const auto [x1, y1] = xy[i];
        if ((x - x0) * (x - x1) <= 0.0 && x0 != x1) {
            const double t = std::log(x / x0) / std::log(x1 / x0);
            return std::exp(std::log(y0) + t * (std::log(y1) - std::log(y0)));
        }
    }
    return -1.0;
}

std::string formatOrDash(double v, const char* format) {
    return v < 0.0 ? std::string("—") : fmt::format(fmt::runtime(format), v);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"vkphoton deposition benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/rooms-10x10.gltf";
    uint32_t width = 160, height = 120, spp = 4, referencePaths = 1600000;
    std::vector<uint32_t> paths{25000, 50000, 100000, 200000, 400000};
    std::vector<uint32_t> depositPaths{100000, 200000, 400000, 800000, 1600000};
    float densityAccuracy = DepositOptions{}.densityAccuracy;
    float epsilon = DepositOptions{}.epsilon;
    bool cutoff = false;
    std::vector<std::string> modeNames{"all", "importance", "density"};
    std::string referencePath;
    std::string device;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--width", width)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--spp", spp)->capture_default_str();
    app.add_option("--paths", paths, "photon paths per render, keeping every photon")->delimiter(',');
    app.add_option("--deposit-paths", depositPaths, "photon paths per render, importance and density")->delimiter(',');
    app.add_option("--density-accuracy", densityAccuracy)->capture_default_str();
    app.add_option("--deposit-epsilon", epsilon)->capture_default_str();
    app.add_flag("--deposit-cutoff", cutoff);
    app.add_option("--modes", modeNames, "deposit modes to measure (all is needed for the summary)")->delimiter(',');
    app.add_option("--reference", referencePath, "EXR: read the reference from it if it exists, else write it there");
    app.add_option("--reference-paths", referencePaths)->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);

    try {
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        Renderer renderer(context, scene);
        fmt::print("scene: {}, {}x{}, {} spp, device: {}; reference: every photon of {} paths\n\n", scenePath, width,
                   height, spp, context.deviceName(), referencePaths);
        ImageRgb reference;
        if (!referencePath.empty() && std::filesystem::exists(referencePath)) {
            reference = readExr(referencePath);
        } else {
            reference = renderer
                            .render<PhotonIntegrator>(frameFor(width, height, spp),
                                                      photonsFor(DepositMode::All, referencePaths))
                            .image;
            if (!referencePath.empty()) writeExr(referencePath, reference);
        }

        const std::map<std::string, DepositMode> known{
            {"all", DepositMode::All}, {"importance", DepositMode::Importance}, {"density", DepositMode::Density}};
        std::vector<std::pair<DepositMode, std::string>> modes;
        for (const std::string& name : modeNames) {
            if (!known.count(name)) throw std::runtime_error("--modes: " + name + " is not all, importance or density");
            modes.emplace_back(known.at(name), name);
        }
        std::map<std::string, std::vector<Point>> curves;
        fmt::print("| deposit | paths | stored photons | photon MB | importon MB | relMSE | photon pass s | render s |\n");
        fmt::print("|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for (const auto& [mode, name] : modes)
            for (const uint32_t n : mode == DepositMode::All ? paths : depositPaths) {
                PhotonIntegratorSettings settings = photonsFor(mode, n);
                settings.deposit.densityAccuracy = densityAccuracy;
                settings.deposit.epsilon = epsilon;
                settings.deposit.cutoff = cutoff;
                const RenderResult r = renderer.render<PhotonIntegrator>(frameFor(width, height, spp), settings);
                const uint64_t stored = r.stats.getOr<uint64_t>("photons.globalStored", 0) +
                                        r.stats.getOr<uint64_t>("photons.causticStored", 0);
                Point p{n, stored, stored * sizeof(gpu::GpuPhoton), relativeMse(r.image, reference),
                        r.stats.get<double>("photons.seconds")};
                curves[name].push_back(p);
                fmt::print("| {} | {} | {} | {:.2f} | {:.2f} | {:.3g} | {:.2f} | {:.2f} |\n", name, n, p.stored,
                           p.bytes / 1048576.0, r.stats.getOr<double>("photons.importonBytes", 0.0) / 1048576.0,
                           p.relMse, p.seconds, r.stats.get<double>("timings.renderSeconds"));
                std::fflush(stdout);
            }

        // Equal error: the error of keeping every photon of the largest path count; equal
        // storage: the photons that keeping every photon of the smallest count stores.
        if (!curves.count("all")) return 0;
        const Point& allBest = curves["all"].back();
        const Point& allSmallest = curves["all"].front();
        fmt::print("\n| deposit | stored photons at relMSE {:.3g} | × fewer than all | relMSE at {} stored photons | × lower than all |\n",
                   allBest.relMse, allSmallest.stored);
        fmt::print("|---|---:|---:|---:|---:|\n");
        for (const auto& [mode, name] : modes) {
            std::vector<std::pair<double, double>> errorToStored, storedToError;
            for (const Point& p : curves[name]) {
                errorToStored.emplace_back(p.relMse, double(p.stored));
                storedToError.emplace_back(double(p.stored), p.relMse);
            }
            std::sort(errorToStored.begin(), errorToStored.end());
            std::sort(storedToError.begin(), storedToError.end());
            const double stored = interpolate(errorToStored, allBest.relMse);
            const double error = interpolate(storedToError, double(allSmallest.stored));
            fmt::print("| {} | {} | {} | {} | {} |\n", name, formatOrDash(stored, "{:.0f}"),
                       formatOrDash(stored > 0 ? allBest.stored / stored : -1.0, "{:.1f}"), formatOrDash(error, "{:.3g}"),
                       formatOrDash(error > 0 ? allSmallest.relMse / error : -1.0, "{:.1f}"));
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}
