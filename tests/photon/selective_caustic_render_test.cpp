// Selective photon update of a moving refractive object (photon/selective_photon_update.h): a
// glass sphere over a floor (test::glassSphereOverFloor) moves; the caustic it focuses moves with it.
// Pilots alone (Dmitriev et al.'s detection) leave stale caustic photons behind; the paths' tracks
// tested against the sphere's old and new bounds find every changed path.
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "gpu_scene/scene_buffers.h"
#include "support/gpu_test_support.h"
#include "photon/scene_changes.h"
#include "photon/photon_map.h"
#include "photon/selective_photon_update.h"
#include "support/test_scenes.h"

namespace vkp {
namespace {

constexpr uint32_t kGroups = 210;  // 2*3*5*7

struct GpuSceneData {
    Scene scene;
    SceneArrays arrays;
    SceneBuffers buffers;
    explicit GpuSceneData(Scene s) : scene(std::move(s)), arrays(buildSceneArrays(scene)), buffers(test::gpu(), arrays) {}
};

// The caustic map's paths (caustic photons only, one slot each) or the global map's.
SelectiveSettings mapSettings(bool caustic, bool tracks, uint32_t budget = 0) {
    SelectiveSettings s;
    s.paths = kGroups * (caustic ? 96 : 32);
    s.maxDeposits = caustic ? 1 : 4;
    s.requiredFlags = caustic ? gpu::kPhotonCaustic : 0u;
    s.seed = 7;
    s.groups = kGroups;
    s.trackPaths = tracks;
    s.budget = budget;
    return s;
}

glm::vec3 at(float x) { return {x, 0.35f, 0.0f}; }

// Caustic photons of a map within `radius` of (x, 0, 0) on the floor.
uint64_t causticPhotonsNear(const std::vector<gpu::GpuPhoton>& photons, float x, float radius) {
    uint64_t n = 0;
    for (const gpu::GpuPhoton& p : photons)
        if ((gpu::photonFlags(p) & gpu::kPhotonCaustic) != 0 && glm::length(p.position - glm::vec3(x, 0, 0)) < radius) ++n;
    return n;
}

class SelectiveCaustic : public test::GpuTest {};

// One move of the sphere by 0.3 (more than its radius): after the update, the tracked selective
// slots equal a full retrace bit for bit in both maps (the diagnostic counts no stale photon) and
// so does the caustic under the sphere's new place; pilots alone leave stale photons behind.
TEST_F(SelectiveCaustic, MovedGlassSphereLeavesNoStalePhotons) {
    GpuSceneData a(test::glassSphereOverFloor(at(-0.5f)));
    GpuSceneData b(test::glassSphereOverFloor(at(-0.2f)));
    for (const bool caustic : {true, false}) {
        SCOPED_TRACE(caustic ? "caustic map" : "global map");
        SelectivePhotonUpdate tracked(test::gpu(), mapSettings(caustic, true));
        SelectivePhotonUpdate pilots(test::gpu(), mapSettings(caustic, false));
        for (SelectivePhotonUpdate* u : {&tracked, &pilots}) {
            u->update(a.scene, a.arrays, a.buffers, false);
            EXPECT_EQ(u->verify().stalePhotons, 0u) << "the first frame is a full trace";
        }
        const SelectiveFrameStats moved = tracked.update(b.scene, b.arrays, b.buffers, false);
        pilots.update(b.scene, b.arrays, b.buffers, false);
        EXPECT_EQ(moved.changedRegions, 2u);  // the sphere's old and new bounds
        EXPECT_GT(moved.stalePathsFound, 0u);
        EXPECT_EQ(moved.stalePathsLeft, 0u);
        EXPECT_LE(moved.photonPathsTraced, tracked.settings().budget);

        const SelectiveVerification exact = tracked.verify();
        EXPECT_EQ(exact.stalePhotons, 0u);
        EXPECT_EQ(exact.stalePaths, 0u);
        // Without the round-robin filling the budget, a frame costs the pilots, the stale paths and
        // one group: what changed, and the same slots.
        SelectiveSettings leanSettings = mapSettings(caustic, true);
        leanSettings.fillBudget = false;
        SelectivePhotonUpdate lean(test::gpu(), leanSettings);
        lean.update(a.scene, a.arrays, a.buffers, false);
        const SelectiveFrameStats leanMoved = lean.update(b.scene, b.arrays, b.buffers, false);
        EXPECT_LE(leanMoved.photonPathsTraced, kGroups + leanMoved.stalePathsFound + lean.pathsInGroup(0));
        EXPECT_LT(leanMoved.photonPathsTraced, moved.photonPathsTraced);
        EXPECT_EQ(lean.verify().stalePhotons, 0u);
        // The old detection misses paths through the small sphere: the diagnostic sees them.
        const SelectiveVerification missed = pilots.verify();
        EXPECT_GT(missed.stalePhotons, 0u);
        EXPECT_GT(missed.staleGroups, 0u);

        if (!caustic) continue;
        // The caustic under the new place, from the selective slots and from a full build.
        PhotonMapSettings ms;
        ms.paths = tracked.settings().paths;
        ms.maxDeposits = 1;
        ms.seed = 7;
        ms.requiredFlags = gpu::kPhotonCaustic;
        PhotonMap full(test::gpu(), b.scene, b.arrays, b.buffers, ms);
        full.build(0);
        PhotonMap fromTracked(test::gpu(), b.scene, b.arrays, b.buffers, ms);
        fromTracked.buildFromSlots(tracked.slots(), 0);
        PhotonMap fromPilots(test::gpu(), b.scene, b.arrays, b.buffers, ms);
        fromPilots.buildFromSlots(pilots.slots(), 0);
        const auto fullPhotons = full.downloadPhotons();
        const uint64_t expected = causticPhotonsNear(fullPhotons, -0.2f, 0.4f);
        ASSERT_GT(expected, 100u) << "the sphere focuses a caustic under it";
        const uint64_t selective = causticPhotonsNear(fromTracked.downloadPhotons(), -0.2f, 0.4f);
        EXPECT_LE(std::abs(double(selective) - double(expected)), 3.0 * std::sqrt(double(expected)));
        EXPECT_EQ(selective, expected);  // bit for bit, in fact
        // What the pilots left: photons of the old caustic away from the new one.
        const uint64_t oldPlaceFull = causticPhotonsNear(fullPhotons, -0.68f, 0.12f);
        const uint64_t oldPlacePilots = causticPhotonsNear(fromPilots.downloadPhotons(), -0.68f, 0.12f);
        EXPECT_GT(oldPlacePilots, oldPlaceFull);
    }
}

// The sphere keeps moving under a budget too small for each frame's stale paths: the stale paths
// found in one frame stay marked (the tracks found them against an older place) until retraced,
// every path that differs from a full retrace is marked, and once the sphere stops the slots
// reach the full retrace exactly.
TEST_F(SelectiveCaustic, StalePathsStayMarkedUntilRetraced) {
    std::vector<std::unique_ptr<GpuSceneData>> scenes;
    for (const float x : {-0.6f, -0.45f, -0.3f, -0.15f}) scenes.push_back(std::make_unique<GpuSceneData>(test::glassSphereOverFloor(at(x))));
    SelectiveSettings s = mapSettings(true, true, kGroups + 100);
    s.refreshGroups = 0;  // the budget's paths for stale paths only
    SelectivePhotonUpdate u(test::gpu(), s);
    u.update(scenes[0]->scene, scenes[0]->arrays, scenes[0]->buffers, false);
    bool pended = false;
    for (size_t f = 1; f < scenes.size() + 40; ++f) {
        const GpuSceneData& now = *scenes[std::min(f, scenes.size() - 1)];
        const SelectiveFrameStats st = u.update(now.scene, now.arrays, now.buffers, false);
        EXPECT_LE(st.photonPathsTraced, s.budget);
        const SelectiveVerification v = u.verify();
        for (uint32_t path : v.differing) EXPECT_TRUE(u.stale(path)) << "path " << path << " frame " << f;
        pended = pended || st.stalePathsLeft > 0;
        if (st.stalePathsLeft == 0 && f >= scenes.size()) {
            EXPECT_EQ(v.stalePhotons, 0u) << "frame " << f;
            break;
        }
    }
    EXPECT_TRUE(pended) << "the budget should have left stale paths for later frames";
    EXPECT_EQ(u.verify().stalePhotons, 0u);
}

// A moved punctual light: exactly its paths are stale (the tracks keep each path's light), the
// other light's paths are kept, and after the update both maps equal a full retrace.
TEST_F(SelectiveCaustic, MovedLightMarksItsPathsOnly) {
    auto twoLights = [](float x) {
        Scene scene = test::glassSphereOverFloor(at(-0.5f));
        test::addPointLight(scene, {x, 1.5f, 0.5f}, glm::vec3(20.0f));
        return scene;
    };
    GpuSceneData a(twoLights(0.8f));
    GpuSceneData b(twoLights(0.9f));
    for (const bool caustic : {true, false}) {
        SCOPED_TRACE(caustic ? "caustic map" : "global map");
        SelectiveSettings s = mapSettings(caustic, true);
        s.budget = s.paths;  // room for every stale path
        SelectivePhotonUpdate u(test::gpu(), s);
        u.update(a.scene, a.arrays, a.buffers, false);
        const auto tracks = u.tracks().download<gpu::GpuPathTrack>(s.paths);
        const uint32_t moved = 1;  // the second punctual light (no emissive triangles)
        uint32_t fromMoved = 0;
        for (const gpu::GpuPathTrack& t : tracks) fromMoved += gpu::pathTrackLight(t) == moved ? 1 : 0;
        ASSERT_GT(fromMoved, s.paths / 4);
        ASSERT_LT(fromMoved, 3 * s.paths / 4);
        const SelectiveFrameStats st = u.update(b.scene, b.arrays, b.buffers, false);
        EXPECT_EQ(st.changedRegions, 0u);
        // The pilots among them were traced before the marks were read: found, not counted twice.
        EXPECT_EQ(st.stalePathsFound, fromMoved);
        EXPECT_EQ(st.stalePathsLeft, 0u);
        EXPECT_EQ(u.verify().stalePhotons, 0u);
    }
}

// Two glass spheres move, one in the camera's view and one behind it; the budget holds about the
// paths the visible one changed. Ordered by the light their stale paths carry in view (Dmitriev et
// al. §5.3), the visible sphere's paths are retraced first; without a camera (energy alone) the
// two are served alike.
TEST_F(SelectiveCaustic, BudgetRetracesWhatTheCameraSeesFirst) {
    auto twoSpheres = [](float a, float b) {
        Scene scene = test::glassSphereOverFloor(at(a));
        scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), at(b)), -1});
        return scene;
    };
    GpuSceneData before(twoSpheres(-1.0f, 1.0f));
    GpuSceneData after(twoSpheres(-0.7f, 1.3f));
    // Looking down at the left sphere's caustic; the right sphere is far outside the view.
    const gpu::GpuCamera camera = makeGpuCamera(test::lookAt({-1.0f, 1.2f, 1.2f}, {-0.9f, 0.0f, 0.0f}, 0.6f), 64, 64);

    // Which paths meet each sphere's old or new bounds (from the tracks of a full trace).
    SelectivePhotonUpdate probe(test::gpu(), mapSettings(true, true));
    probe.update(before.scene, before.arrays, before.buffers, false);
    const auto tracks = probe.tracks().download<gpu::GpuPathTrack>(probe.settings().paths);
    const SceneSnapshot sBefore = snapshotScene(before.scene, before.arrays, 0);
    const SceneChanges changes = sceneChanges(sBefore, snapshotScene(after.scene, after.arrays, 0));
    ASSERT_EQ(changes.regions.size(), 4u);  // left old, left new, right old, right new
    std::vector<char> left(tracks.size(), 0), right(tracks.size(), 0);
    uint32_t leftCount = 0, rightCount = 0;
    for (size_t p = 0; p < tracks.size(); ++p) {
        for (size_t r = 0; r < 4; ++r) {
            if (!gpu::pathTrackMeetsBox(tracks[p], changes.regions[r].min, changes.regions[r].max)) continue;
            (r < 2 ? left : right)[p] = 1;
        }
        leftCount += left[p] && !right[p] ? 1 : 0;
        rightCount += right[p] && !left[p] ? 1 : 0;
    }
    ASSERT_GT(leftCount, 100u);
    ASSERT_GT(rightCount, 100u);

    auto retracedShares = [&](const gpu::GpuCamera* view) {
        SelectiveSettings s = mapSettings(true, true, kGroups + leftCount);
        s.refreshGroups = 0;
        SelectivePhotonUpdate u(test::gpu(), s);
        u.update(before.scene, before.arrays, before.buffers, false, 0, view);
        const SelectiveFrameStats st = u.update(after.scene, after.arrays, after.buffers, false, 0, view);
        EXPECT_GT(st.stalePathsLeft, 0u) << "the budget holds about half the stale paths";
        uint32_t leftDone = 0, rightDone = 0;
        for (uint32_t p = kGroups; p < tracks.size(); ++p) {  // pilots (paths < kGroups) are always traced
            leftDone += left[p] && !right[p] && !u.stale(p) ? 1 : 0;
            rightDone += right[p] && !left[p] && !u.stale(p) ? 1 : 0;
        }
        return std::make_pair(double(leftDone) / leftCount, double(rightDone) / rightCount);
    };
    const auto [leftInView, rightOutOfView] = retracedShares(&camera);
    EXPECT_GT(leftInView, 0.8);
    EXPECT_LT(rightOutOfView, 0.3);
    const auto [leftNoView, rightNoView] = retracedShares(nullptr);
    EXPECT_LT(std::abs(leftNoView - rightNoView), 0.5 * (leftInView - rightOutOfView));
}

// `render --frames --verify-update` on scenes/glass-moving.gltf: every frame's stats hold each
// map's stale photons against a full retrace: none with the tracks, some with pilots alone; the
// flags need --frames and the selective update.
TEST(SelectiveCausticCli, VerifyUpdateReportsStalePhotonsPerFrameAndMap) {
    const std::filesystem::path dir = test::freshTempDir("selective", "verify");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/glass-moving.gltf";
    const std::string common = "--width 24 --height 24 --spp 1 --integrator photon --photons 4000 --caustic-photons 20000 "
                               "--gather-rays 0 --quiet --frames 0:3 --verify-update";
    uint64_t stale[2] = {0, 0};
    for (const int pilots : {0, 1}) {
        const std::string name = pilots ? "pilots" : "tracks";
        auto run = test::runVkphoton(fmt::format("render {} {} --photon-detect {} -o {}/{}-#.exr --stats-json {}/{}.json", scene,
                                           common, name, dir.string(), name, dir.string(), name));
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_NE(run.output.find("frame 3: verify-update:"), std::string::npos) << run.output;
        std::ifstream in(dir / (name + ".json"));
        const nlohmann::json stats = nlohmann::json::parse(in);
        ASSERT_EQ(stats["frames"].size(), 4u);
        for (const auto& frame : stats["frames"]) {
            ASSERT_EQ(frame["verify"]["maps"].size(), 2u);  // the global and the caustic map
            EXPECT_EQ(frame["verify"]["maps"][1]["map"], "caustic");
            stale[pilots] += frame["verify"]["stalePhotons"].get<uint64_t>();
        }
        EXPECT_EQ(stats["verifyUpdate"]["stalePhotons"].get<uint64_t>(), stale[pilots]);
    }
    EXPECT_EQ(stale[0], 0u) << "the tracks find every changed path";
    EXPECT_GT(stale[1], 0u) << "pilots alone miss some";
    // The options of the selective update are refused without it, naming the option and what it needs.
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"--verify-update", "--verify-update is read only with --frames"},
        {"--frames 0:1 --photon-update full --verify-update", "--verify-update is read only with --photon-update selective"},
        {"--photon-detect pilots", "--photon-detect is read only with --frames"}};
    for (const auto& [flags, message] : refused) {
        const auto run = test::runVkphoton(fmt::format("render {} {} -o {}/bad-#.exr --quiet", scene, flags, dir.string()));
        EXPECT_EQ(run.exitCode, 2) << flags;
        EXPECT_NE(run.output.find(message), std::string::npos) << run.output;
    }
}

// Regions: an instance's world bounds under its transform, widened by the ray-offset margin; a
// moved light's index; merging keeps every region inside the union that replaces it.
TEST(SceneChanges, MovedInstanceGivesItsOldAndNewBounds) {
    const Scene a = test::glassSphereOverFloor(at(-0.5f));
    const Scene b = test::glassSphereOverFloor(at(-0.2f));
    const SceneArrays arraysA = buildSceneArrays(a), arraysB = buildSceneArrays(b);
    const SceneSnapshot sa = snapshotScene(a, arraysA, 0), sb = snapshotScene(b, arraysB, 0);
    EXPECT_FALSE(sceneChanges(sa, sa).any());
    EXPECT_EQ(sa.staticHash, sb.staticHash);  // the static triangles and materials are the same
    const SceneChanges c = sceneChanges(sa, sb);
    ASSERT_EQ(c.regions.size(), 2u);
    EXPECT_FALSE(c.unknown);
    EXPECT_TRUE(c.lights.empty());
    EXPECT_NEAR(c.regions[0].center().x, -0.5f, 1e-4f);
    EXPECT_NEAR(c.regions[1].center().x, -0.2f, 1e-4f);
    EXPECT_GT(c.regions[1].extent().x, 0.5f);  // 2 r and the margin
    EXPECT_LT(c.regions[1].extent().x, 0.51f);

    Scene lit = a;
    lit.lights[0].position.x += 0.1f;
    SceneArrays arraysLit = buildSceneArrays(lit);
    const SceneChanges l = sceneChanges(sa, snapshotScene(lit, arraysLit, 0));
    EXPECT_TRUE(l.regions.empty());
    EXPECT_EQ(l.lights.size(), 1u);

    Scene floor = a;
    floor.triangles[0].p[0].y += 0.01f;  // what no region bounds: the static triangles
    SceneArrays arraysFloor = buildSceneArrays(floor);
    EXPECT_TRUE(sceneChanges(sa, snapshotScene(floor, arraysFloor, 1)).unknown);

    std::vector<Bounds> many;
    for (int i = 0; i < 10; ++i) many.push_back({glm::vec3(float(i), 0, 0), glm::vec3(float(i) + 0.5f, 1, 1)});
    const std::vector<Bounds> merged = mergeRegions(many, 3);
    ASSERT_EQ(merged.size(), 3u);
    for (const Bounds& r : many) {
        bool inside = false;
        for (const Bounds& m : merged)
            inside = inside || (glm::all(glm::greaterThanEqual(r.min, m.min)) && glm::all(glm::lessThanEqual(r.max, m.max)));
        EXPECT_TRUE(inside);
    }
}

}  // namespace
}  // namespace vkp
