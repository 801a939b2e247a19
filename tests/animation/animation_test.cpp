// glTF animation (docs/animation.md): every interpolation against hand-computed values, slerp
// the short way, frame ranges and output names, bad animations (clear message, exit 2).
// `render --frames` end to end is in animation_frames_slow_test.cpp.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/base64.h"
#include "support/cli_runner.h"
#include "image/exr.h"
#include "animation/frame_sequence.h"
#include "scene/animation.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::freshTempDir;
using test::runVkphoton;

AnimationChannel channel(AnimationPath path, Interpolation interpolation, std::vector<float> times,
                         std::vector<glm::vec4> values) {
    AnimationChannel c;
    c.node = 0;
    c.path = path;
    c.interpolation = interpolation;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

TEST(AnimationSampling, LinearTranslationAndClamping) {
    const AnimationChannel c = channel(AnimationPath::Translation, Interpolation::Linear, {1.0f, 3.0f},
                                       {glm::vec4(0, 2, 4, 0), glm::vec4(4, 2, 0, 0)});
    EXPECT_EQ(sampleChannel(c, 2.0), glm::dvec4(2, 2, 2, 0));
    EXPECT_EQ(sampleChannel(c, 1.5), glm::dvec4(1, 2, 3, 0));
    EXPECT_EQ(sampleChannel(c, 0.0), glm::dvec4(0, 2, 4, 0));   // before the first key: the first value
    EXPECT_EQ(sampleChannel(c, 9.0), glm::dvec4(4, 2, 0, 0));   // after the last: the last
}

TEST(AnimationSampling, StepHoldsTheKeyBefore) {
    const AnimationChannel c = channel(AnimationPath::Scale, Interpolation::Step, {0.0f, 1.0f, 2.0f},
                                       {glm::vec4(1, 1, 1, 0), glm::vec4(2, 2, 2, 0), glm::vec4(3, 3, 3, 0)});
    EXPECT_EQ(sampleChannel(c, 0.99), glm::dvec4(1, 1, 1, 0));
    EXPECT_EQ(sampleChannel(c, 1.0), glm::dvec4(2, 2, 2, 0));
    EXPECT_EQ(sampleChannel(c, 1.5), glm::dvec4(2, 2, 2, 0));
    EXPECT_EQ(sampleChannel(c, 5.0), glm::dvec4(3, 3, 3, 0));
}

TEST(AnimationSampling, CubicSplineScalesTangentsByTheInterval) {
    // Keys at t = 0 and 2 (interval 2): values 0 and 1, out-tangent of key 0 = 3, in-tangent of
    // key 1 = 1, so m0 = 6 and m1 = 2. Hermite at s = 0.25: h10 = 0.140625, h01 = 0.15625,
    // h11 = -0.046875: 0.84375 + 0.15625 - 0.09375 = 0.90625. At s = 0.5: 0.75 + 0.5 - 0.25 = 1.
    const glm::vec4 unused(99.0f);
    const AnimationChannel c = channel(
        AnimationPath::Translation, Interpolation::CubicSpline, {0.0f, 2.0f},
        {unused, glm::vec4(0, 0, 0, 0), glm::vec4(3, 0, 0, 0), glm::vec4(1, 0, 0, 0), glm::vec4(1, 0, 0, 0), unused});
    EXPECT_DOUBLE_EQ(sampleChannel(c, 0.5).x, 0.90625);
    EXPECT_DOUBLE_EQ(sampleChannel(c, 1.0).x, 1.0);
    EXPECT_EQ(sampleChannel(c, -1.0).x, 0.0);  // clamped: the value, not a tangent
    EXPECT_EQ(sampleChannel(c, 3.0).x, 1.0);
}

TEST(AnimationSampling, LinearRotationSlerpsTheShortWay) {
    const double h = std::sqrt(0.5);
    // Identity to 90 degrees about z, the second given as its negative (the same rotation): the
    // short way passes 45 degrees about z at the middle, not -135.
    const AnimationChannel c = channel(AnimationPath::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                                       {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, float(-h), float(-h))});
    const glm::dvec4 q = sampleChannel(c, 0.5);
    const double s = std::sin(M_PI / 8.0), co = std::cos(M_PI / 8.0);
    EXPECT_NEAR(std::abs(q.z), s, 1e-6);
    EXPECT_NEAR(std::abs(q.w), co, 1e-6);
    EXPECT_GT(q.z * q.w, 0.0);  // the same sign: +45 degrees, not -135
    // A third of the way between identity and 90 degrees about x: 30 degrees.
    const glm::dvec4 third = slerpShortest({0, 0, 0, 1}, {h, 0, 0, h}, 1.0 / 3.0);
    EXPECT_NEAR(third.x, std::sin(M_PI / 12.0), 1e-6);
    EXPECT_NEAR(third.w, std::cos(M_PI / 12.0), 1e-6);
}

TEST(FrameSequence, RangesAndNames) {
    EXPECT_EQ(parseFrameRange("3:7").first, 3u);
    EXPECT_EQ(parseFrameRange("3:7").count(), 5u);
    EXPECT_EQ(parseFrameRange("4").last, 4u);
    for (const char* bad : {"", "7:3", "a:b", "-1:2", "1:", ":2", "1:2:3", "0:100000"})
        EXPECT_THROW(parseFrameRange(bad), InputError) << bad;
    EXPECT_EQ(frameOutputPath("out/frame-####.exr", 7), fs::path("out/frame-0007.exr"));
    EXPECT_EQ(frameOutputPath("f#.exr", 123), fs::path("f123.exr"));
    EXPECT_EQ(frameOutputPath("a##b###.exr", 5), fs::path("a05b005.exr"));
    EXPECT_EQ(frameOutputPath("d##/f-##.exr", 1), fs::path("d##/f-01.exr"));  // the file name only
    EXPECT_TRUE(hasFramePattern("out/f-##.exr"));
    EXPECT_FALSE(hasFramePattern("out#/f.exr"));
    EXPECT_DOUBLE_EQ(frameTime(12, 24.0), 0.5);
}

using test::base64;

// A one-triangle scene with node 0 animated by `animation` (JSON) over `times` and `outputs`
// (floats, appended to the buffer after the triangle).
fs::path writeAnimated(const fs::path& dir, const std::string& name, const std::vector<float>& times,
                       const std::vector<float>& outputs, const json& channel, const std::string& outputType = "VEC3",
                       const std::string& interpolation = "LINEAR") {
    std::vector<float> floats{0, 0, 0, 1, 0, 0, 0, 1, 0};
    floats.insert(floats.end(), times.begin(), times.end());
    floats.insert(floats.end(), outputs.begin(), outputs.end());
    std::vector<uint8_t> bytes(floats.size() * 4);
    std::memcpy(bytes.data(), floats.data(), bytes.size());
    const size_t components = outputType == "VEC4" ? 4 : 3;
    json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}, {"translation", {0.5, 0, 0}}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
        {"buffers", {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", times.size() * 4}},
          {{"buffer", 0}, {"byteOffset", 36 + times.size() * 4}, {"byteLength", outputs.size() * 4}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", times.size()}, {"type", "SCALAR"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", outputs.size() / components}, {"type", outputType}}}},
        {"animations", {{{"samplers", {{{"input", 1}, {"output", 2}, {"interpolation", interpolation}}}},
                         {"channels", {channel}}}}},
    };
    const fs::path path = dir / name;
    std::ofstream(path) << doc.dump();
    return path;
}

const json kTranslation = {{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}};

// World x of the first vertex the scene draws: a flattened triangle, or (animated nodes' meshes
// are instances, docs/bvh.md) the first instance's first triangle through its transform.
float firstDrawnVertexX(const Scene& scene) {
    if (!scene.triangles.empty()) return scene.triangles.front().p[0].x;
    const Instance& instance = scene.instances.at(0);
    return (instance.transform * glm::vec4(scene.meshes.at(instance.mesh).triangles.at(0).p[0], 1.0f)).x;
}

TEST(AnimationInput, AnimatedSceneMovesTheNode) {
    const fs::path dir = freshTempDir("animation", "moves");
    GltfSceneSource source(writeAnimated(dir, "ok.gltf", {0, 1}, {0, 0, 0, 2, 0, 0}, kTranslation));
    EXPECT_FLOAT_EQ(firstDrawnVertexX(source.sceneAt(0.5)), 1.0f);
    EXPECT_FLOAT_EQ(firstDrawnVertexX(source.sceneAt(7.0)), 2.0f);
    EXPECT_FLOAT_EQ(firstDrawnVertexX(source.stillScene()), 0.5f);  // the static translation
}

TEST(AnimationInput, BadAnimationsGiveClearMessages) {
    const fs::path dir = freshTempDir("animation", "bad");
    const auto message = [&](const fs::path& path) {
        try {
            GltfSceneSource source(path);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(writeAnimated(dir, "count.gltf", {0, 1, 2}, {0, 0, 0, 1, 1, 1}, kTranslation)).find("2 output values for 3 key times"),
              std::string::npos);
    EXPECT_NE(message(writeAnimated(dir, "order.gltf", {0, 1, 1}, {0, 0, 0, 1, 1, 1, 2, 2, 2}, kTranslation))
                  .find("must increase strictly"),
              std::string::npos);
    EXPECT_NE(message(writeAnimated(dir, "nan.gltf", {0, 1}, {0, 0, 0, NAN, 1, 1}, kTranslation)).find("NaN"),
              std::string::npos);
    json missing = kTranslation;
    missing["target"]["node"] = 5;
    EXPECT_NE(message(writeAnimated(dir, "node.gltf", {0, 1}, {0, 0, 0, 1, 1, 1}, missing)).find("nodes[5] does not exist"),
              std::string::npos);
    json path = kTranslation;
    path["target"]["path"] = "colour";
    EXPECT_NE(message(writeAnimated(dir, "path.gltf", {0, 1}, {0, 0, 0, 1, 1, 1}, path)).find("unknown path"),
              std::string::npos);
    EXPECT_NE(message(writeAnimated(dir, "cubic.gltf", {0, 1}, {0, 0, 0, 1, 1, 1}, kTranslation, "VEC3", "CUBICSPLINE"))
                  .find("CUBICSPLINE needs 6"),
              std::string::npos);
    EXPECT_NE(message(writeAnimated(dir, "interp.gltf", {0, 1}, {0, 0, 0, 1, 1, 1}, kTranslation, "VEC3", "SMOOTH"))
                  .find("interpolation"),
              std::string::npos);
    // The message names the file and the element; the CLI exits 2.
    const fs::path bad = writeAnimated(dir, "count2.gltf", {0, 1, 2}, {0, 0, 0, 1, 1, 1}, kTranslation);
    EXPECT_NE(message(bad).find("count2.gltf: animations[0].samplers[0]"), std::string::npos) << message(bad);
    const test::RunResult run = runVkphoton(fmt::format("render {} --frames 0:1 -o {}/f-#.exr --quiet", bad.string(),
                                                        dir.string()));
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("output values"), std::string::npos) << run.output;
}

TEST(AnimationCli, FlagsNeedTheirPartners) {
    const fs::path dir = freshTempDir("animation", "flags");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/cornell-moving.gltf";
    auto run = runVkphoton(fmt::format("render {} --frames 0:1 -o {}/no-number.exr --quiet", scene, dir.string()));
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.output.find("run of '#'"), std::string::npos) << run.output;
    run = runVkphoton(fmt::format("render {} --fps 30 -o {}/a.exr --quiet", scene, dir.string()));
    EXPECT_EQ(run.exitCode, 2);
    run = runVkphoton(fmt::format("render {} --frames 2:1 -o {}/a-#.exr --quiet", scene, dir.string()));
    EXPECT_EQ(run.exitCode, 2);
    run = runVkphoton(fmt::format("render {} --frames 0:0 --animation 3 -o {}/a-#.exr --quiet", scene, dir.string()));
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.output.find("--animation 3"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace vkp
