// render --frames without per-frame rebuilds (animation/frame_scene.h, docs/animation.md "Per
// frame"): the scene built once and moved in place (instances, punctual lights, cameras) equals a
// fresh build of the frame's scene, byte for byte; what cannot be moved in place rebuilds; and a
// frame rendered in a sequence equals the same frame rendered alone, bit for bit.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "gpu_scene/scene_buffers.h"
#include "support/gpu_test_support.h"
#include "image/exr.h"
#include "animation/frame_scene.h"
#include "vk/buffer.h"
#include "support/test_scenes.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

template <typename T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

Scene withLights(Scene scene, glm::vec3 pointAt, glm::vec3 spotAim) {
    test::addPointLight(scene, pointAt, glm::vec3(2.0f));
    test::addSunAndSpot(scene, glm::vec3(1.0f), glm::vec3(3.0f));
    scene.lights.back().direction = glm::normalize(spotAim);
    return scene;
}

// The same room with every instance moved and the punctual lights moved.
Scene movedScene(const Scene& base, uint32_t seed) {
    Scene moved = base;
    std::mt19937 rng(seed);
    for (Instance& instance : moved.instances) instance.transform = test::randomTransform(rng, base.bounds, 0.2f);
    moved.lights[0].position += glm::vec3(0.1f, -0.2f, 0.05f);
    moved.lights[2].position += glm::vec3(-0.3f, 0.0f, 0.2f);
    moved.lights[2].direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.3f));
    moved.cameras.push_back(test::lookAt({0.0f, 1.0f, 3.0f}, {0.0f, 1.0f, 0.0f}));
    return moved;
}

class FrameSceneTest : public test::GpuTest {};

TEST_F(FrameSceneTest, InPlaceUpdateEqualsAFreshBuild) {
    const Scene a = withLights(test::instancedCornell(6, 3), {0.0f, 1.5f, 0.0f}, {0.4f, -1.0f, -0.4f});
    ASSERT_FALSE(a.instances.empty());
    const Scene b = movedScene(a, 11);
    ASSERT_EQ(FrameScene::whyNotInPlace(a, b), "");

    FrameScene frames(test::gpu(), LightSampling{});
    EXPECT_TRUE(frames.set(a).rebuilt);
    const FrameSceneChange change = frames.set(b);
    EXPECT_FALSE(change.rebuilt) << change.reason;
    EXPECT_EQ(frames.generation(), 1u);
    const SceneArrays fresh = buildSceneArrays(b);
    const SceneArrays& updated = frames.renderer().gpuScene().arrays();
    EXPECT_TRUE(sameBytes(updated.nodes, fresh.nodes));
    EXPECT_TRUE(sameBytes(updated.topLevel.instances, fresh.topLevel.instances));
    EXPECT_TRUE(sameBytes(updated.triangles, fresh.triangles));
    EXPECT_TRUE(sameBytes(updated.lights, fresh.lights));
    EXPECT_TRUE(sameBytes(updated.lightCdf, fresh.lightCdf));
    ASSERT_EQ(frames.scene().cameras.size(), a.cameras.size() + 1);  // the frame's cameras, for makeFrame
    EXPECT_EQ(frames.scene().cameras.back().position, b.cameras.back().position);
    EXPECT_FALSE(sameBytes(updated.lightCdf, buildSceneArrays(a).lightCdf));  // the light tree moved too
}

TEST_F(FrameSceneTest, WhatCannotMoveInPlaceRebuilds) {
    const Scene a = withLights(test::instancedCornell(2, 5), {0.0f, 1.5f, 0.0f}, {0.4f, -1.0f, -0.4f});
    FrameScene frames(test::gpu(), LightSampling{});
    frames.set(a);

    Scene brighter = a;
    brighter.lights[0].intensity *= 2.0f;  // another light power: another CDF
    FrameSceneChange change = frames.set(brighter);
    EXPECT_TRUE(change.rebuilt);
    EXPECT_NE(change.reason.find("punctual light"), std::string::npos) << change.reason;

    Scene staticMoved = a;
    staticMoved.triangles[0].p[0].x += 0.01f;  // flattened geometry (an animated emissive mesh)
    change = frames.set(staticMoved);
    EXPECT_TRUE(change.rebuilt);
    EXPECT_NE(change.reason.find("static"), std::string::npos) << change.reason;
    EXPECT_EQ(frames.generation(), 3u);

    FrameScene always(test::gpu(), LightSampling{}, /*alwaysRebuild=*/true);
    always.set(a);
    EXPECT_TRUE(always.set(a).rebuilt);
}

// --light-sampler photon: a frame that moves instances and punctual lights in place traces the
// light cells again in the moved scene: the light-selection data (CPU copy and GPU buffer) equal a
// fresh build of the moved scene word for word; a frame in which nothing moved keeps its cells.
TEST_F(FrameSceneTest, PhotonLightCellsFollowInPlaceMotion) {
    const Scene a = withLights(test::instancedCornell(6, 3), {0.0f, 1.5f, 0.0f}, {0.4f, -1.0f, -0.4f});
    const Scene b = movedScene(a, 11);
    LightSampling sampling;
    sampling.sampler = LightSampler::Photon;
    sampling.cellPhotons = 20000;
    FrameScene frames(test::gpu(), sampling);
    frames.set(a);
    const std::vector<float> before = frames.renderer().gpuScene().arrays().lightCdf;
    ASSERT_TRUE(frames.renderer().lightCells());
    EXPECT_GT(frames.renderer().lightCells()->cells, 0u);

    const FrameSceneChange still = frames.set(a);
    EXPECT_FALSE(still.rebuilt) << still.reason;
    EXPECT_EQ(still.lightCellSeconds, 0.0);
    EXPECT_TRUE(sameBytes(frames.renderer().gpuScene().arrays().lightCdf, before));

    const FrameSceneChange change = frames.set(b);
    EXPECT_FALSE(change.rebuilt) << change.reason;
    EXPECT_GT(change.lightCellSeconds, 0.0);
    const std::vector<float>& updated = frames.renderer().gpuScene().arrays().lightCdf;
    EXPECT_FALSE(sameBytes(updated, before));  // the cells moved with the lights and occluders
    const Renderer fresh(test::gpu(), b, sampling);
    EXPECT_TRUE(sameBytes(updated, fresh.gpuScene().arrays().lightCdf));
    // The GPU buffer (with headroom after the data) holds the same words.
    const vk::Buffer& buffer = *frames.renderer().gpuScene().buffers().bindings().buffers[gpu::kSceneLightCdfBinding];
    std::vector<float> uploaded = buffer.download<float>();
    ASSERT_GE(uploaded.size(), updated.size());
    uploaded.resize(updated.size());
    EXPECT_TRUE(sameBytes(uploaded, updated));
}

// cornell-moving.gltf's sphere is an instance: frames 1 and 2 of a sequence move it in place
// (no rebuild) and frame 2 equals frame 2 rendered alone (built from scratch) bit for bit.
TEST(FrameSceneCli, FrameInASequenceEqualsTheFrameAlone) {
    const fs::path dir = test::freshTempDir("frame_scene", "alone");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/cornell-moving.gltf";
    const std::string common = "--width 16 --height 16 --spp 1 --integrator photon --photons 1000 --caustic-photons 1000 "
                               "--gather-rays 0 --quiet --validate --photon-update full";
    auto run = test::runVkphoton(fmt::format("render {} {} --frames 0:2 -o {}/s-#.exr --stats-json {}/s.json", scene,
                                             common, dir.string(), dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    run = test::runVkphoton(fmt::format("render {} {} --frames 2 -o {}/a-#.exr", scene, common, dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(readExr(dir / "s-2.exr").pixels, readExr(dir / "a-2.exr").pixels);
    EXPECT_NE(readExr(dir / "s-1.exr").pixels, readExr(dir / "a-2.exr").pixels);  // it moved

    std::ifstream in(dir / "s.json");
    const json stats = json::parse(in);
    ASSERT_EQ(stats["frames"].size(), 3u);
    EXPECT_TRUE(stats["frames"][0]["sceneRebuilt"].get<bool>());
    for (int i = 1; i < 3; ++i) {
        EXPECT_FALSE(stats["frames"][i]["sceneRebuilt"].get<bool>()) << stats["frames"][i]["sceneRebuildReason"];
        EXPECT_GE(stats["frames"][i]["bvhSeconds"].get<double>(), 0.0);
    }
}

// --tile and --aov per frame: each frame's part (with the merge attributes) and its AOV channels,
// under the frame's ####-name.
TEST(FrameSceneCli, TilesAndAovsPerFrame) {
    const fs::path dir = test::freshTempDir("frame_scene", "parts");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/cornell-moving.gltf";
    const std::string common = "--width 16 --height 16 --spp 1 --quiet --validate --frames 3:4";
    auto run = test::runVkphoton(fmt::format("render {} {} --tile 2/2 -o {}/t-#.exr", scene, common, dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    run = test::runVkphoton(fmt::format("render {} {} -o {}/f-#.exr --aov albedo", scene, common, dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (int f = 3; f <= 4; ++f) {
        ExrAttributes attributes;
        const ImageRgb part = readExr(dir / fmt::format("t-{}.exr", f), &attributes);
        const ImageRgb whole = readExr(dir / fmt::format("f-{}.exr", f));
        EXPECT_EQ(part.width, 16u);
        EXPECT_EQ(part.height, 8u);
        // The tile's pixels are the whole frame's lower band.
        EXPECT_TRUE(std::equal(part.pixels.begin(), part.pixels.end(), whole.pixels.begin() + 8 * 16 * 3));
        EXPECT_EQ(readExrChannel(dir / fmt::format("f-{}.exr", f), "Albedo.R").size(), 16u * 16u);
        bool tagged = false;
        for (const auto& [key, value] : attributes) tagged = tagged || key.find("crop") != std::string::npos;
        EXPECT_TRUE(tagged);
    }
    run = test::runVkphoton(fmt::format("render {} {} --tile 1/2 --aov albedo -o {}/x-#.exr", scene, common, dir.string()));
    EXPECT_EQ(run.exitCode, 2) << run.output;
    run = test::runVkphoton(fmt::format("render {} --scene-update rebuild -o {}/y.exr --quiet", scene, dir.string()));
    EXPECT_EQ(run.exitCode, 2) << run.output;  // needs --frames
    EXPECT_NE(run.output.find("--scene-update"), std::string::npos) << run.output;
    run = test::runVkphoton(fmt::format("render {} {} --scene-update sometimes -o {}/z-#.exr", scene, common, dir.string()));
    EXPECT_EQ(run.exitCode, 2) << run.output;
}

}  // namespace
}  // namespace vkp
