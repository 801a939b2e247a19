// Direct-light time per frame, raster (stencil shadow volumes, RGBA mask, lighting pass:
// host/passes/raster_direct_pass.h) against traced (the same lighting with one shadow ray per
// pixel and light through the BVH: bench/shaders/traced_direct.comp), for N point lights placed on
// a jittered grid inside the scene's bounds. Both give the exact (noise-free) direct light of all
// N lights at the pixel centres. Usage:
//   build/bench/raster_direct_bench [SCENE] [--width W --height H --lights 1,4,16,64 --repeat R --device D]
// Prints a Markdown table for docs/benchmarks.md.
#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "median.h"
#include "passes/raster_direct_pass.h"
#include "passes/raster_lights.h"
#include "gpu_scene/scene_buffers.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "vk/buffer.h"
#include "shaders/bench_kernels.glsl"
#include "vk/kernel.h"
#include "vk/context.h"
#include "vk/shader_registry.h"

namespace vkp::embedded {
extern const vk::ShaderEntry* const vkphoton_bench_shaders_table[];
}

namespace {

using Clock = std::chrono::steady_clock;

// Point lights spread through the middle of the bounds (deterministic).
std::vector<vkp::gpu::GpuLight> pointLights(const vkp::Bounds& bounds, uint32_t count) {
    std::vector<vkp::gpu::GpuLight> lights;
    for (uint32_t i = 0; i < count; ++i) {
        const float fx = 0.2f + 0.6f * ((i * 37u) % 64u) / 63.0f;
        const float fy = 0.35f + 0.5f * ((i * 11u) % 16u) / 15.0f;
        const float fz = 0.2f + 0.6f * ((i * 23u) % 32u) / 31.0f;
        vkp::gpu::GpuLight l{};
        l.type = vkp::gpu::kLightPoint;
        l.position = bounds.min + glm::vec3(fx, fy, fz) * bounds.extent();
        l.intensity = glm::vec3(1.0f / static_cast<float>(count));
        lights.push_back(l);
    }
    return lights;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace vkp;
    CLI::App app{"vkphoton raster vs traced direct light benchmark"};
    std::string scenePath = std::string(VKPHOTON_SOURCE_DIR) + "/scenes/cornell-box.gltf";
    uint32_t width = 256, height = 256, repeat = 3;
    std::vector<uint32_t> lightCounts{1, 4, 16, 64};
    std::string device;
    app.add_option("scene", scenePath, "glTF scene")->capture_default_str();
    app.add_option("--width", width)->capture_default_str();
    app.add_option("--height", height)->capture_default_str();
    app.add_option("--lights", lightCounts, "point light counts")->delimiter(',');
    app.add_option("--repeat", repeat, "repetitions (the median is reported)")->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);

    try {
        vk::registerShaderTable(embedded::vkphoton_bench_shaders_table);
        const Scene scene = loadGltf(scenePath);
        vk::Context context({false, device});
        const SceneArrays arrays = buildSceneArrays(scene);
        const SceneBuffers buffers(context, arrays);
        const gpu::GpuCamera camera = makeGpuCamera(chooseCamera(scene, -1), width, height);
        const float near = rasterNearPlane(scene.bounds);
        const uint64_t pixels = uint64_t(width) * height;

        fmt::print("scene: {} ({} triangles), {}x{}, device: {}, median of {}\n", scenePath,
                   arrays.triangles.size(), width, height, context.deviceName(), repeat);
        fmt::print("| point lights | raster, compute volumes ms/frame | raster, geometry shader ms/frame | traced ms/frame | traced / raster (compute) | max abs difference raster-traced (compute / GS) |\n");
        fmt::print("|---:|---:|---:|---:|---:|---:|\n");
        for (uint32_t count : lightCounts) {
            const auto lights = pointLights(scene.bounds, count);
            RasterDirectPass raster(context, arrays, buffers, lights, width, height);
            std::unique_ptr<RasterDirectPass> rasterGs;
            if (context.geometryShaderEnabled())
                rasterGs = std::make_unique<RasterDirectPass>(context, arrays, buffers, lights, width, height,
                                                              VolumeGeometry::GeometryShader);
            vk::Buffer traced(context, "traced direct", pixels * sizeof(glm::vec4), vk::kStorageUsage);
            vk::Kernel<gpu::TracedDirectKernel> kernel(context);
            kernel.bind(buffers.bindings());
            kernel.bind(gpu::kTracedDirectLightBinding, raster.shadows().lights());
            kernel.bind(gpu::kTracedDirectOutputBinding, traced);

            std::vector<double> rasterTimes, gsTimes, tracedTimes;
            for (uint32_t r = 0; r < repeat + 1; ++r) {  // the first run warms up
                auto start = Clock::now();
                context.submitAndWait([&](VkCommandBuffer cmd) { raster.record(cmd, camera, near); });
                if (r > 0) rasterTimes.push_back(std::chrono::duration<double>(Clock::now() - start).count());
                if (rasterGs) {
                    start = Clock::now();
                    context.submitAndWait([&](VkCommandBuffer cmd) { rasterGs->record(cmd, camera, near); });
                    if (r > 0) gsTimes.push_back(std::chrono::duration<double>(Clock::now() - start).count());
                }
                start = Clock::now();
                context.submitAndWait([&](VkCommandBuffer cmd) {
                    traced.fillZero(cmd);
                    vk::transferToComputeBarrier(cmd);
                    for (uint32_t i = 0; i < count; ++i) {
                        gpu::RasterDirectParams params{};
                        params.camera = camera;
                        params.width = width;
                        params.height = height;
                        params.firstLight = i;
                        params.lightCount = 1;
                        kernel.record(cmd, pixels, params);
                        vk::computeBarrier(cmd);
                    }
                });
                if (r > 0) tracedTimes.push_back(std::chrono::duration<double>(Clock::now() - start).count());
            }
            // Same answer check: the two methods differ only on pixels at shadow edges.
            const auto a = raster.direct().download<glm::vec4>();
            const auto b = traced.download<glm::vec4>();
            const auto g = rasterGs ? rasterGs->direct().download<glm::vec4>() : a;
            double maxDiff = 0.0, maxDiffGs = 0.0;
            for (uint64_t i = 0; i < pixels; ++i) {
                maxDiff = std::max<double>(maxDiff, glm::length(glm::vec3(a[i]) - glm::vec3(b[i])));
                maxDiffGs = std::max<double>(maxDiffGs, glm::length(glm::vec3(g[i]) - glm::vec3(b[i])));
            }
            const double rasterMs = 1e3 * bench::median(rasterTimes), tracedMs = 1e3 * bench::median(tracedTimes);
            const double gsMs = gsTimes.empty() ? 0.0 : 1e3 * bench::median(gsTimes);
            fmt::print("| {} | {:.1f} | {:.1f} | {:.1f} | {:.2f} | {:.3g} / {:.3g} |\n", count, rasterMs, gsMs, tracedMs,
                       tracedMs / rasterMs, maxDiff, maxDiffGs);
        }
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
}
