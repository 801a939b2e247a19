// `render --frames` end to end (docs/animation.md): the rest pose renders bit-identical to the still
// scene, frames differ where the object moved, --stats-json has one "frames" entry per frame, and
// the selective photon update traces fewer paths than a full retrace and agrees with it.
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

std::vector<float> pixels(const fs::path& exr) { return readExr(exr).pixels; }

// cornell-moving.gltf's sphere sits at its static translation at t = 0 (and t = 2 s: frame 48 at
// 24 fps) with keys exact in float: those frames must equal the still render bit for bit.
TEST(AnimationFrames, RestPoseIsBitIdenticalAndStatsListFrames) {
    const fs::path dir = freshTempDir("animation", "frames");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/cornell-moving.gltf";
    const std::string common = "--width 24 --height 24 --spp 2 --integrator photon --photons 2000 --caustic-photons 2000 "
                               "--gather-rays 0 --quiet --validate";
    auto run = runVkphoton(fmt::format("render {} {} -o {}/still.exr", scene, common, dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    run = runVkphoton(fmt::format("render {} {} --frames 0:1 -o {}/f-###.exr --photon-update full --stats-json {}/s.json", scene, common,
                                  dir.string(), dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ASSERT_TRUE(fs::exists(dir / "f-000.png"));
    EXPECT_EQ(pixels(dir / "f-000.exr"), pixels(dir / "still.exr"));
    EXPECT_NE(pixels(dir / "f-001.exr"), pixels(dir / "still.exr"));  // the sphere moved 5 cm
    run = runVkphoton(fmt::format("render {} {} --frames 48 -o {}/g-##.exr", scene, common, dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(pixels(dir / "g-48.exr"), pixels(dir / "still.exr"));

    std::ifstream in(dir / "s.json");
    const json stats = json::parse(in);
    ASSERT_TRUE(stats.contains("frames"));
    ASSERT_EQ(stats["frames"].size(), 2u);
    for (int i = 0; i < 2; ++i) {
        const json& f = stats["frames"][i];
        EXPECT_EQ(f["frame"].get<int>(), i);
        EXPECT_EQ(f["photonPathsTraced"].get<uint64_t>(), 4000u);  // global + caustic paths, all retraced
        EXPECT_EQ(f["groupsRetraced"].get<uint64_t>(), 0u);
        EXPECT_GT(f["seconds"].get<double>(), 0.0);
        EXPECT_GT(f["sceneUpdateSeconds"].get<double>(), 0.0);
    }
    EXPECT_DOUBLE_EQ(stats["frames"][1]["time"].get<double>(), 1.0 / 24.0);
}

// --photon-update selective (the default) against full: frame 0 traces every path either way; later
// frames trace fewer paths (pilots + retraced groups) and their images agree within noise.
TEST(AnimationFrames, SelectiveUpdateTracesFewerPathsAndAgreesWithFull) {
    const fs::path dir = freshTempDir("animation", "selective");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/cornell-moving.gltf";
    const std::string common = "--width 24 --height 24 --spp 4 --integrator photon --photons 8000 --caustic-photons 2000 "
                               "--gather-rays 0 --quiet --validate --frames 0:3";
    auto run = runVkphoton(fmt::format("render {} {} -o {}/s-#.exr --photon-budget 2000 --stats-json {}/s.json", scene,
                                       common, dir.string(), dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    run = runVkphoton(fmt::format("render {} {} -o {}/f-#.exr --photon-update full --stats-json {}/f.json", scene,
                                  common, dir.string(), dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream sin(dir / "s.json"), fin(dir / "f.json");
    const json sel = json::parse(sin), full = json::parse(fin);
    ASSERT_EQ(sel["frames"].size(), 4u);
    EXPECT_EQ(sel["frames"][0]["photonPathsTraced"].get<uint64_t>(), 10000u);
    EXPECT_EQ(pixels(dir / "s-0.exr"), pixels(dir / "f-0.exr"));
    for (int i = 1; i < 4; ++i) {
        const json& s = sel["frames"][i];
        EXPECT_EQ(full["frames"][i]["photonPathsTraced"].get<uint64_t>(), 10000u);
        EXPECT_LE(s["photonPathsTraced"].get<uint64_t>(), 4000u);  // budget 2000 per map, two maps
        EXPECT_GT(s["photonPathsTraced"].get<uint64_t>(), 0u);
        const std::vector<float> a = pixels(dir / fmt::format("s-{}.exr", i)), b = pixels(dir / fmt::format("f-{}.exr", i));
        double sa = 0.0, sb = 0.0;
        for (size_t k = 0; k < a.size(); ++k) {
            sa += a[k];
            sb += b[k];
        }
        EXPECT_NEAR(sa / sb, 1.0, 0.05) << "frame " << i;
    }
}


// hall-moving.gltf: a 0.5 m sphere in a 20 x 10 x 5 m hall. Frame 48 (24 fps) is the sphere's last
// 6 cm of motion, frame 49 has nothing moving (the keys end at 2 s): pilots change only where
// their paths meet the sphere, so few groups are marked in frame 48 and none in frame 49.
TEST(AnimationFrames, HallMovingMarksFewGroupsAndNoneOnceStill) {
    const fs::path dir = freshTempDir("animation", "hall");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/hall-moving.gltf";
    const auto run = runVkphoton(fmt::format("render {} --width 16 --height 12 --spp 1 --integrator photon --photons 40000 "
                                             "--caustic-photons 20000 --gather-rays 0 --quiet --validate --frames 47:49 "
                                             "-o {}/h-##.exr --stats-json {}/h.json",
                                             scene, dir.string(), dir.string()));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(dir / "h.json");
    const json frames = json::parse(in)["frames"];
    ASSERT_EQ(frames.size(), 3u);
    const uint64_t groups = frames[0]["groupsRetraced"].get<uint64_t>();  // frame 47 traces every group of both maps
    EXPECT_GT(groups, 0u);
    EXPECT_FALSE(frames[1]["sceneRebuilt"].get<bool>());  // the sphere is an instance, moved in place
    const uint64_t marked = frames[1]["groupsMarked"].get<uint64_t>();
    EXPECT_GT(frames[1]["changedPilots"].get<uint64_t>(), 0u);
    EXPECT_GT(marked, 0u);
    EXPECT_LT(marked, groups / 20) << "a 0.5 m sphere in a 20 m hall changes few pilots";
    EXPECT_EQ(frames[2]["changedPilots"].get<uint64_t>(), 0u) << "nothing moves from 2 s on";
    EXPECT_EQ(frames[2]["groupsMarked"].get<uint64_t>(), 0u);
    EXPECT_EQ(frames[2]["groupsPending"].get<uint64_t>(), 0u);
}

}  // namespace
}  // namespace vkp
