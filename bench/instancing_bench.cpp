// Two-level BVH and instancing (docs/bvh.md, docs/benchmarks.md): on a generated scene of N
// instances of one sphere mesh (a ground quad and a point light besides), the instanced form
// against the flattened one (every instance's triangles copied to world space): glTF load time
// (EXT_mesh_gpu_instancing file written to --dir), scene-array build time (BVH included), device
// bytes, camera and diffuse-bounce rays/s; then the per-frame update of every instance's
// transform (top level rebuilt or refitted, uploaded) against a full rebuild and upload. Usage:
//   build/bench/instancing_bench [--instances N] [--rings R] [--segments S] [--flatten-max T]
//                                [--ray-size W] [--repeat K] [--dir D] [--device D]
// The flattened form is measured only up to --flatten-max drawn triangles (memory).
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "median.h"
#include "gpu_scene/scene_buffers.h"
#include "render/frame.h"
#include "scene/gltf_loader.h"
#include "shaders/bench_kernels.glsl"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/kernel.h"
#include "vk/shader_registry.h"

namespace vkp::embedded {
extern const vk::ShaderEntry* const vkphoton_bench_shaders_table[];
}

namespace {

using namespace vkp;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

template <typename T> void append(std::vector<uint8_t>& bytes, const T& v) {
    const auto* p = reinterpret_cast<const uint8_t*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

struct Placement {
    glm::vec3 translation;
    glm::quat rotation;
    glm::vec3 scale;
    glm::mat4 matrix() const {
        return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
    }
};

// Instances on a square grid with random rotations and scales; `phase` moves them (per frame).
std::vector<Placement> placements(uint32_t count, float phase) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const auto side = static_cast<uint32_t>(std::ceil(std::sqrt(double(count))));
    std::vector<Placement> out;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 axis = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) + glm::vec3(1e-3f));
        const float angle = 6.2831853f * u(rng) + phase;
        const float s = 0.6f + 0.6f * u(rng);
        const glm::vec3 at(3.0f * float(i % side), 1.0f + 0.5f * std::sin(phase + float(i)), 3.0f * float(i / side));
        out.push_back({at, glm::angleAxis(angle, axis), glm::vec3(s, s * (0.7f + 0.6f * u(rng)), s)});
    }
    return out;
}

// A glTF file: one UV-sphere mesh (smooth normals) drawn by a node with EXT_mesh_gpu_instancing,
// a ground quad, a point light.
std::filesystem::path writeScene(const std::filesystem::path& dir, uint32_t instances, int rings, int segments) {
    std::vector<uint8_t> bytes;
    std::vector<glm::vec3> positions;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j <= segments; ++j) {
            const float theta = float(i) / rings * 3.14159265f, phi = float(j) / segments * 6.28318531f;
            positions.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        }
    std::vector<uint32_t> indices;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const uint32_t a = i * (segments + 1) + j, b = a + segments + 1;
            if (i > 0) indices.insert(indices.end(), {a, a + 1, b});
            if (i + 1 < rings) indices.insert(indices.end(), {a + 1, b + 1, b});
        }
    const auto side = static_cast<float>(std::ceil(std::sqrt(double(instances))));
    const std::vector<glm::vec3> ground = {{-3, 0, -3}, {3 * side, 0, -3}, {3 * side, 0, 3 * side}, {-3, 0, 3 * side}};
    const std::vector<uint32_t> groundIndices = {0, 2, 1, 0, 3, 2};
    nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array();
    const auto add = [&](const void* data, size_t size, size_t count, int componentType, const char* type) {
        const size_t offset = bytes.size();
        bytes.insert(bytes.end(), static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + size);
        while (bytes.size() % 4) bytes.push_back(0);
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
        accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", componentType}, {"count", count}, {"type", type}});
        return accessors.size() - 1;
    };
    const size_t pos = add(positions.data(), positions.size() * 12, positions.size(), 5126, "VEC3");
    accessors[pos]["min"] = {-1, -1, -1};
    accessors[pos]["max"] = {1, 1, 1};
    const size_t nor = add(positions.data(), positions.size() * 12, positions.size(), 5126, "VEC3");
    const size_t idx = add(indices.data(), indices.size() * 4, indices.size(), 5125, "SCALAR");
    const size_t gpos = add(ground.data(), ground.size() * 12, ground.size(), 5126, "VEC3");
    accessors[gpos]["min"] = {-3, 0, -3};
    accessors[gpos]["max"] = {3 * side, 0, 3 * side};
    const size_t gidx = add(groundIndices.data(), groundIndices.size() * 4, groundIndices.size(), 5125, "SCALAR");
    std::vector<glm::vec3> t, s;
    std::vector<glm::vec4> r;
    for (const Placement& p : placements(instances, 0.0f)) {
        t.push_back(p.translation);
        r.emplace_back(p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w);
        s.push_back(p.scale);
    }
    const size_t ta = add(t.data(), t.size() * 12, t.size(), 5126, "VEC3");
    const size_t ra = add(r.data(), r.size() * 16, r.size(), 5126, "VEC4");
    const size_t sa = add(s.data(), s.size() * 12, s.size(), 5126, "VEC3");
    const nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"EXT_mesh_gpu_instancing", "KHR_lights_punctual"}},
        {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 2.0e6}}}}}}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0, 1, 2}}}}},
        {"nodes",
         {{{"mesh", 0},
           {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", ta}, {"ROTATION", ra}, {"SCALE", sa}}}}}}}},
          {{"mesh", 1}},
          {{"translation", {1.5 * side, 4.0 * side, 1.5 * side}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}},
        {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.7, 0.6, 1}}, {"metallicFactor", 0}}}}}},
        {"meshes",
         {{{"primitives", {{{"attributes", {{"POSITION", pos}, {"NORMAL", nor}}}, {"indices", idx}, {"material", 0}}}}},
          {{"primitives", {{{"attributes", {{"POSITION", gpos}}}, {"indices", gidx}, {"material", 0}}}}}}},
        {"buffers", {{{"byteLength", bytes.size()}, {"uri", "instancing-bench.bin"}}}},
        {"bufferViews", views},
        {"accessors", accessors}};
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "instancing-bench.bin", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::ofstream(dir / "instancing-bench.gltf") << doc.dump();
    return dir / "instancing-bench.gltf";
}

uint64_t deviceBytes(const SceneArrays& a) {
    return a.nodes.size() * sizeof(gpu::GpuBvhNode) + a.triangles.size() * sizeof(gpu::GpuTriangle) +
           a.shading.size() * sizeof(gpu::GpuTriangleShading) + a.instanceBytes().size();
}

struct Measured {
    double loadSeconds = 0, buildSeconds = 0, bvhSeconds = 0, cameraMrays = 0, bounceMrays = 0;
    uint64_t bytes = 0, storedTriangles = 0;
};

Measured measure(vk::Context& context, const std::filesystem::path& path, uint64_t instanceMinTriangles,
                 uint32_t raySize, uint32_t repeat, Scene* keep = nullptr) {
    Measured m;
    GltfLimits limits;
    limits.instanceMinTriangles = instanceMinTriangles;
    auto start = Clock::now();
    Scene scene = loadGltf(path, limits);
    m.loadSeconds = since(start);
    start = Clock::now();
    const SceneArrays arrays = buildSceneArrays(scene);
    m.buildSeconds = since(start);
    m.bvhSeconds = arrays.bvhBuildSeconds;
    m.bytes = deviceBytes(arrays);
    m.storedTriangles = arrays.triangles.size();
    const SceneBuffers buffers(context, arrays);
    const uint64_t pixels = uint64_t(raySize) * raySize;
    vk::Buffer result(context, "hit counts", pixels * sizeof(uint32_t), vk::kStorageUsage);
    vk::Kernel<gpu::RayBenchKernel> kernel(context);
    kernel.bind(buffers.bindings());
    kernel.bind(gpu::kRayBenchResultBinding, result);
    gpu::RayBenchParams push{makeGpuCamera(chooseCamera(scene, -1), raySize, raySize), raySize, raySize, 0, 0};
    const auto timeMode = [&](uint32_t mode) {
        std::vector<double> times;
        for (uint32_t r = 0; r < repeat + 1; ++r) {
            push.mode = mode;
            push.seed = r;
            const auto t0 = Clock::now();
            context.submitAndWait([&](VkCommandBuffer cmd) { kernel.record(cmd, pixels, push); });
            if (r > 0) times.push_back(since(t0));
        }
        return bench::median(times);
    };
    const double camera = timeMode(0), bounce = timeMode(1);
    uint64_t bounceRays = 0, cameraRays = 0;
    for (uint32_t h : result.download<uint32_t>()) {
        bounceRays += h >= 1;
        cameraRays += 1;
    }
    m.cameraMrays = cameraRays / camera / 1e6;
    m.bounceMrays = bounceRays / std::max(bounce - camera, 1e-9) / 1e6;
    if (keep) *keep = std::move(scene);
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"vkphoton two-level BVH / instancing benchmark"};
    uint32_t instances = 625, raySize = 512, repeat = 3;
    int rings = 64, segments = 128;
    uint64_t flattenMax = 3'000'000;
    std::string dir = (std::filesystem::temp_directory_path() / "vkphoton-instancing-bench").string(), device;
    app.add_option("--instances", instances)->capture_default_str();
    app.add_option("--rings", rings)->capture_default_str();
    app.add_option("--segments", segments)->capture_default_str();
    app.add_option("--flatten-max", flattenMax, "measure the flattened form up to this many drawn triangles")
        ->capture_default_str();
    app.add_option("--ray-size", raySize)->capture_default_str();
    app.add_option("--repeat", repeat)->capture_default_str();
    app.add_option("--dir", dir, "where the generated glTF goes")->capture_default_str();
    app.add_option("--device", device);
    CLI11_PARSE(app, argc, argv);
    try {
        vk::registerShaderTable(embedded::vkphoton_bench_shaders_table);
        vk::Context context({false, device});
        const std::filesystem::path path = writeScene(dir, instances, rings, segments);
        Scene scene;
        const Measured inst = measure(context, path, 64, raySize, repeat, &scene);
        uint64_t drawn = scene.triangles.size();
        for (const Instance& i : scene.instances) drawn += scene.meshes[i.mesh].triangles.size();
        fmt::print("scene: {} instances of a {}-triangle sphere + ground ({} drawn triangles), rays at {}x{}, device: {}\n",
                   scene.instances.size(), scene.meshes.empty() ? 0 : scene.meshes[0].triangles.size(), drawn, raySize,
                   raySize, context.deviceName());
        fmt::print("| form | glTF load | scene arrays (BVH) | device bytes | stored triangles | camera rays | bounce rays |\n"
                   "|---|---|---|---|---|---|---|\n");
        const auto row = [](const char* form, const Measured& m) {
            fmt::print("| {} | {:.2f} s | {:.2f} s ({:.2f} s) | {:.1f} MiB | {} | {:.2f} Mrays/s | {:.2f} Mrays/s |\n", form,
                       m.loadSeconds, m.buildSeconds, m.bvhSeconds, m.bytes / 1048576.0, m.storedTriangles, m.cameraMrays,
                       m.bounceMrays);
        };
        row("instanced", inst);
        if (drawn <= flattenMax) row("flattened", measure(context, path, UINT64_MAX, raySize, repeat));
        else fmt::print("| flattened | not measured: {} drawn triangles > --flatten-max {} | | | | | |\n", drawn, flattenMax);

        // Per-frame update: every instance moves.
        SceneArrays arrays = buildSceneArrays(scene);
        SceneBuffers buffers(context, arrays);
        std::vector<double> rebuild, refit, upload, full;
        for (uint32_t r = 0; r < repeat + 1; ++r) {
            std::vector<glm::mat4> transforms;
            for (const Placement& p : placements(uint32_t(scene.instances.size()), 0.1f * float(r + 1)))
                transforms.push_back(p.matrix());
            auto t0 = Clock::now();
            updateInstances(arrays.nodes, arrays.topLevel, transforms, TopLevelUpdate::Rebuild);
            const double rb = since(t0);
            t0 = Clock::now();
            buffers.updateInstances(arrays);
            const double up = since(t0);
            t0 = Clock::now();
            updateInstances(arrays.nodes, arrays.topLevel, transforms, TopLevelUpdate::Refit);
            const double rf = since(t0);
            for (size_t i = 0; i < transforms.size(); ++i) scene.instances[i].transform = transforms[i];
            t0 = Clock::now();
            const SceneArrays fresh = buildSceneArrays(scene);
            const SceneBuffers freshBuffers(context, fresh);
            const double fl = since(t0);
            if (r == 0) continue;  // warm-up
            rebuild.push_back(rb);
            refit.push_back(rf);
            upload.push_back(up);
            full.push_back(fl);
        }
        fmt::print("\nper-frame update of {} instance transforms (median of {}):\n| step | time |\n|---|---|\n",
                   scene.instances.size(), repeat);
        fmt::print("| top level rebuilt (binned SAH) | {:.3f} ms |\n", 1e3 * bench::median(rebuild));
        fmt::print("| top level refitted | {:.3f} ms |\n", 1e3 * bench::median(refit));
        fmt::print("| upload of instances + top-level nodes | {:.3f} ms |\n", 1e3 * bench::median(upload));
        fmt::print("| full rebuild: buildSceneArrays + upload | {:.1f} ms |\n", 1e3 * bench::median(full));
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
}
