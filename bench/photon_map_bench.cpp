// Photon map benchmark: grid build time per million photons, gather queries per second (fixed
// radius, k nearest, one nearest), maps of millions of photons (--map-photons: build time,
// gather rate, memory), and image error against time for the path tracer and the photon
// integrator (two-pass and progressive) on one scene. Usage:
//   build/bench/photon_map_bench [SCENE] [--size N --reference-spp N --reference FILE.exr
//                                 --max-seconds S --repeat R --device D --map-photons 4,16,64
//                                 --skip-grid --skip-convergence --segment-shift N]
// Prints Markdown tables for docs/benchmarks.md. The reference (path tracer, --reference-spp) is
// written to --reference when that file does not exist and read from it when it does.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "median.h"
#include "image/metrics.h"
#include "gpu_scene/scene_buffers.h"
#include "reference_image.h"
#include "photon/photon_map.h"
#include "photon/photon_integrator.h"
#include "photon/progressive_photon_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "util/stopwatch.h"
#include "vk/buffer.h"
#include "shaders/bench_kernels.glsl"
#include "vk/kernel.h"
#include "vk/context.h"
#include "vk/shader_registry.h"

namespace vkp::embedded {
extern const vk::ShaderEntry* const vkphoton_bench_shaders_table[];
}

namespace {

using namespace vkp;



void benchGrid(vk::Context& context, const Scene& scene, uint32_t paths, uint32_t repeat, uint32_t segmentShift) {
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(context, arrays);
    PhotonMapSettings settings;
    settings.paths = paths;
    settings.cellSize = 0.03f;
    settings.segmentShift = segmentShift;
    PhotonMap map(context, scene, arrays, buffers, settings);
    std::vector<double> grid, gridCpu, trace;
    PhotonMapStats stats;
    for (uint32_t r = 0; r <= repeat; ++r) {
        stats = map.build(r * paths);
        if (r > 0) {
            grid.push_back(stats.gridSeconds);
            gridCpu.push_back(stats.gridCpuSeconds);
            trace.push_back(stats.traceSeconds);
        }
    }
    const double millions = stats.stored / 1e6;
    fmt::print("\n### Photon map build ({} paths, {} photons stored, {} chunk(s), segments of {} photons)\n\n", paths,
               stats.stored, stats.chunks, map.segmentPhotons());
    fmt::print("| measure | value |\n|---|---|\n");
    fmt::print("| tracing + compaction | {:.3f} s ({:.2f} M paths/s) |\n", bench::median(trace), paths / bench::median(trace) / 1e6);
    fmt::print("| grid build (count, scan, scatter, sort, copy) | {:.3f} s per million photons |\n",
               bench::median(grid) / millions);
    fmt::print("| grid build, CPU time of every thread | {:.3f} CPU s per million photons |\n",
               bench::median(gridCpu) / millions);

    // Gathers at every 8th photon of the map: where the scene's surfaces are.
    const uint32_t stride = 8;
    const uint32_t queries = static_cast<uint32_t>(stats.stored / stride);
    vk::Buffer results(context, "results", std::max<VkDeviceSize>(16, queries * sizeof(float)), vk::kStorageUsage);
    vk::Kernel<gpu::GatherBenchKernel> kernel(context);
    kernel.bind(gpu::kGatherBenchGridBinding, map.grid().cellStart());
    kernel.bind(gpu::kGatherBenchGridBinding + 1, map.grid().photons());
    kernel.bind(gpu::kGatherBenchResultBinding, results);
    fmt::print("\n### Gathers ({} queries at photon positions, cell size {} m)\n\n", queries, settings.cellSize);
    fmt::print("| query | queries/s | queries per CPU second |\n|---|---|---|\n");
    struct Mode { const char* name; uint32_t mode, k; float radius; };
    for (const Mode& m : {Mode{"fixed radius 0.03 m, cone filter", 0, 0, 0.03f},
                          Mode{"32 nearest within 0.06 m", 1, 32, 0.06f},
                          Mode{"nearest within 0.03 m", 2, 1, 0.03f}}) {
        gpu::GatherBenchParams push{map.grid().view(map.photonPower()), queries, stride, m.mode, m.k, m.radius};
        std::vector<double> times, cpuTimes;
        for (uint32_t r = 0; r <= repeat; ++r) {
            const auto start = Clock::now();
            const double cpuStart = processCpuSeconds();
            context.submitAndWait([&](VkCommandBuffer cmd) { kernel.record(cmd, queries, push); });
            if (r > 0) {
                times.push_back(secondsSince(start));
                cpuTimes.push_back(processCpuSeconds() - cpuStart);
            }
        }
        fmt::print("| {} | {:.3f} M | {:.3f} M |\n", m.name, queries / bench::median(times) / 1e6,
                   queries / bench::median(cpuTimes) / 1e6);
    }
}

// Gather queries per second at `queries` photons spread over the map's grid (every stride-th).
double gatherRate(vk::Context& context, const PhotonMap& map, uint32_t queries, uint32_t stride, uint32_t mode,
                  uint32_t k, float radius) {
    vk::Buffer results(context, "results", std::max<VkDeviceSize>(16, queries * sizeof(float)), vk::kStorageUsage);
    vk::Kernel<gpu::GatherBenchKernel> kernel(context);
    kernel.bind(gpu::kGatherBenchGridBinding, map.grid().cellStart());
    kernel.bind(gpu::kGatherBenchGridBinding + 1, map.grid().photons());
    kernel.bind(gpu::kGatherBenchResultBinding, results);
    gpu::GatherBenchParams push{map.grid().view(map.photonPower()), queries, stride, mode, k, radius};
    context.submitAndWait([&](VkCommandBuffer cmd) { kernel.record(cmd, queries / 16, push); });  // warm-up
    const auto start = Clock::now();
    context.submitAndWait([&](VkCommandBuffer cmd) { kernel.record(cmd, queries, push); });
    return queries / secondsSince(start);
}

// Maps of about `millions` M photons each (paths from a pilot map's photons per path): one build
// each (tracing + compaction, grid), the device memory of the map and its grid, and gathers at
// 2^18 photons spread over the whole map. The cell size follows the map's density as the photon
// integrator's does (the radius of a disk holding 32 photons if they spread evenly over the
// scene's surfaces): fixed-radius sums within one cell, 32 nearest within two, the nearest within
// one, so each query visits about as many photons whatever the map's size.
void benchMapSizes(vk::Context& context, const Scene& scene, const std::vector<uint32_t>& millions) {
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(context, arrays);
    PhotonMapSettings settings;
    settings.paths = 100000;
    const double area = sceneSurfaceArea(arrays);
    settings.cellSizeFor = [area](uint64_t photons) { return evenSpreadRadius(32, photons, area); };
    double photonsPerPath = 0.0;
    {
        PhotonMap pilot(context, scene, arrays, buffers, settings);
        photonsPerPath = double(pilot.build(0).stored) / settings.paths;
    }
    fmt::print("\n### Photon maps of millions of photons ({:.3f} photons per path)\n\n", photonsPerPath);
    fmt::print("| photons stored | paths | buffers (map) | trace + compaction | grid build | map + grid memory | cell r | "
               "fixed radius r | 32 nearest within 2r | nearest within r |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (uint32_t m : millions) {
        settings.paths = static_cast<uint32_t>(std::ceil(m * 1e6 / photonsPerPath));
        PhotonMap map(context, scene, arrays, buffers, settings);
        const PhotonMapStats stats = map.build(0);
        const uint32_t queries = static_cast<uint32_t>(std::min<uint64_t>(stats.stored, 1u << 18));
        const uint32_t stride = static_cast<uint32_t>(std::max<uint64_t>(1, stats.stored / queries));
        const float r = stats.cellSize;
        const double fixed = gatherRate(context, map, queries, stride, 0, 0, r);
        const double nearestK = gatherRate(context, map, queries, stride, 1, 32, 2.0f * r);
        const double nearest = gatherRate(context, map, queries, stride, 2, 1, r);
        fmt::print("| {} | {} | {} | {:.1f} s | {:.1f} s | {:.0f} MiB | {:.4f} m | {:.3f} M/s | {:.3f} M/s | {:.3f} M/s |\n",
                   stats.stored, settings.paths, (stats.stored + map.segmentPhotons() - 1) / map.segmentPhotons(),
                   stats.traceSeconds, stats.gridSeconds, stats.bytes / 1048576.0, r, fixed / 1e6, nearestK / 1e6,
                   nearest / 1e6);
        std::fflush(stdout);
    }
}

void benchConvergence(vk::Context& context, const Scene& scene, uint32_t size, uint32_t referenceSpp,
                      const std::filesystem::path& referencePath, double maxSeconds) {
    Renderer renderer(context, scene);
    FrameSettings base;
    base.width = size;
    base.height = size;
    base.seed = 1;
    fmt::print("\n");
    const ImageRgb reference = bench::referenceImage(renderer, base, referenceSpp, referencePath);
    fmt::print("\n### Error against time, {}x{} (relMSE against the reference)\n\n", size, size);
    fmt::print("| integrator | spp | seconds | relMSE |\n|---|---|---|---|\n");
    enum class Kind { Path, Photon, Progressive };
    struct Method { const char* name; Kind kind; };
    for (const Method& m : {Method{"path", Kind::Path}, Method{"photon", Kind::Photon},
                            Method{"photon --progressive", Kind::Progressive}}) {
        for (uint32_t spp = 1;; spp *= 2) {
            FrameSettings s = base;
            s.samplesPerPixel = spp;
            const PhotonIntegratorSettings photon;
            const RenderResult r = m.kind == Kind::Path     ? renderer.render<PathIntegrator>(s)
                                   : m.kind == Kind::Photon ? renderer.render<PhotonIntegrator>(s, photon)
                                                            : renderer.render<ProgressivePhotonIntegrator>(s, photon);
            const auto seconds = r.stats.get<double>("timings.renderSeconds");
            fmt::print("| {} | {} | {:.2f} | {:.5f} |\n", m.name, spp, seconds, relativeMse(r.image, reference));
            std::fflush(stdout);
            if (seconds * 2.0 > maxSeconds) break;
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"vkphoton photon map benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/cornell-glass.gltf";
    uint32_t paths = 1000000, repeat = 3, size = 128, referenceSpp = 2048, segmentShift = 0;
    double maxSeconds = 60.0;
    std::string device, referencePath;
    bool skipConvergence = false, skipGrid = false;
    std::vector<uint32_t> mapMillions;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--paths", paths, "photon paths for the build and gather measurements")->capture_default_str();
    app.add_option("--segment-shift", segmentShift,
                   "segments of 2^N photons for the --paths map (0: the default, 4 M): the general form of the "
                   "segmented kernels on a map of several segments")->capture_default_str();
    app.add_option("--repeat", repeat, "runs after a warm-up (the median is reported)")->capture_default_str();
    app.add_option("--size", size, "image size of the error-against-time runs")->capture_default_str();
    app.add_option("--reference-spp", referenceSpp, "path-traced reference samples per pixel")->capture_default_str();
    app.add_option("--reference", referencePath, "reference EXR: read if it exists, else rendered and written");
    app.add_option("--max-seconds", maxSeconds, "longest render per integrator in the error curve")->capture_default_str();
    app.add_flag("--skip-convergence", skipConvergence, "only the build and gather measurements");
    app.add_flag("--skip-grid", skipGrid, "leave out the build and gather measurements of --paths");
    app.add_option("--map-photons", mapMillions, "maps of these many million photons: build, gathers, memory")
        ->delimiter(',');
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        vk::registerShaderTable(embedded::vkphoton_bench_shaders_table);
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        fmt::print("scene: {} ({} triangles), device: {}\n", scenePath, scene.triangles.size(), context.deviceName());
        if (!skipGrid) benchGrid(context, scene, paths, repeat, segmentShift);
        if (!mapMillions.empty()) benchMapSizes(context, scene, mapMillions);
        if (!skipConvergence) benchConvergence(context, scene, size, referenceSpp, referencePath, maxSeconds);
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
}
