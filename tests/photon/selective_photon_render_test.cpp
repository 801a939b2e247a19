// Selective photon update (photon/selective_photon_update.h): two scenes built in code that
// differ by one moved box.
#include <cstring>
#include <set>

#include <gtest/gtest.h>

#include "gpu_scene/scene_buffers.h"
#include "support/gpu_test_support.h"
#include "render/frame.h"
#include "photon/importon_map.h"
#include "photon/photon_map.h"
#include "photon/selective_photon_update.h"
#include "support/test_scenes.h"

namespace vkp {
namespace {

constexpr uint32_t kGroups = 210;  // 2*3*5*7
constexpr uint32_t kPaths = kGroups * 16;
constexpr uint32_t kDeposits = 4;

Scene boxScene(glm::vec3 boxLo) {
    Scene scene = test::shadowTestScene();
    test::addQuad(scene, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});  // floor, facing up
    test::addQuad(scene, {-2, 3, -2}, {2, 3, -2}, {2, 3, 2}, {-2, 3, 2});  // ceiling, facing down
    test::addBox(scene, boxLo, boxLo + glm::vec3(1.0f));
    test::addPointLight(scene, {0.0f, 2.0f, 0.0f}, glm::vec3(10.0f));
    return scene;
}

struct GpuSceneData {
    Scene scene;
    SceneArrays arrays;
    SceneBuffers buffers;
    explicit GpuSceneData(Scene s) : scene(std::move(s)), arrays(buildSceneArrays(scene)), buffers(test::gpu(), arrays) {}
};

SelectiveSettings settings(uint32_t budget = 0) {
    SelectiveSettings s;
    s.paths = kPaths;
    s.maxDeposits = kDeposits;
    s.seed = 7;
    s.groups = kGroups;
    s.pilotsPerGroup = 1;
    s.budget = budget;
    return s;
}

bool samePhotons(const std::vector<gpu::GpuPhoton>& a, const std::vector<gpu::GpuPhoton>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(gpu::GpuPhoton)) == 0;
}

class SelectivePhoton : public test::GpuTest {};

// After the motion stops and every group has been retraced since, the persistent slots equal a full
// trace of the final scene bit for bit, and so does the compacted map.
TEST_F(SelectivePhoton, ConvergesToTheFullRetraceBitIdentically) {
    GpuSceneData a(boxScene({-1.5f, 0.0f, -0.5f}));
    GpuSceneData b(boxScene({0.5f, 0.0f, -0.5f}));
    SelectivePhotonUpdate selective(test::gpu(), settings(kGroups + 20 * 16));
    selective.update(a.scene, a.arrays, a.buffers, false);
    const uint64_t firstStill = selective.frame() + 1;
    bool converged = false;
    for (int frame = 0; frame < 64 && !converged; ++frame) {
        selective.update(b.scene, b.arrays, b.buffers, false);
        converged = true;
        for (uint32_t g = 0; g < kGroups; ++g) converged = converged && selective.lastTraced(g) >= firstStill;
    }
    ASSERT_TRUE(converged);

    SelectivePhotonUpdate full(test::gpu(), settings());
    full.update(b.scene, b.arrays, b.buffers, true);
    const std::vector<gpu::GpuPhoton> expected = full.downloadSlots();
    EXPECT_TRUE(samePhotons(selective.downloadSlots(), expected));
    // The full update's slots are a plain contiguous trace (paths 0 .. kPaths - 1).
    PhotonTracer tracer(test::gpu(), b.scene, b.arrays, b.buffers);
    PhotonSettings ps;
    ps.paths = kPaths;
    ps.maxDeposits = kDeposits;
    ps.seed = 7;
    tracer.trace(ps);
    EXPECT_TRUE(samePhotons(tracer.downloadPhotons(), expected));

    // Stale slots (scene a) must differ, or the test proves nothing.
    SelectivePhotonUpdate stale(test::gpu(), settings());
    stale.update(a.scene, a.arrays, a.buffers, true);
    EXPECT_FALSE(samePhotons(stale.downloadSlots(), expected));

    PhotonMapSettings ms;
    ms.paths = kPaths;
    ms.maxDeposits = kDeposits;
    ms.seed = 7;
    PhotonMap built(test::gpu(), b.scene, b.arrays, b.buffers, ms);
    built.build(0);
    PhotonMap fromSlots(test::gpu(), b.scene, b.arrays, b.buffers, ms);
    const PhotonMapStats st = fromSlots.buildFromSlots(selective.slots(), 0);
    EXPECT_GT(st.stored, 0u);
    EXPECT_TRUE(samePhotons(fromSlots.downloadPhotons(), built.downloadPhotons()));
    EXPECT_EQ(fromSlots.photonPower(), built.photonPower());
}

// A pilot whose photons change with the move marks its group; a group whose pilot is unchanged is
// not marked.
TEST_F(SelectivePhoton, ChangedPilotsMarkTheirGroupsOnly) {
    GpuSceneData a(boxScene({-1.5f, 0.0f, -0.5f}));
    GpuSceneData b(boxScene({0.5f, 0.0f, -0.5f}));
    SelectivePhotonUpdate fullA(test::gpu(), settings()), fullB(test::gpu(), settings());
    fullA.update(a.scene, a.arrays, a.buffers, true);
    fullB.update(b.scene, b.arrays, b.buffers, true);
    const auto slotsA = fullA.downloadSlots(), slotsB = fullB.downloadSlots();
    std::set<uint32_t> expected;
    for (uint32_t p = 0; p < kGroups; ++p)  // pilot of group p is path p
        if (std::memcmp(&slotsA[p * kDeposits], &slotsB[p * kDeposits], kDeposits * sizeof(gpu::GpuPhoton)) != 0)
            expected.insert(p);
    ASSERT_GT(expected.size(), 0u);
    ASSERT_LT(expected.size(), kGroups);

    SelectivePhotonUpdate selective(test::gpu(), settings());
    selective.update(a.scene, a.arrays, a.buffers, false);
    const SelectiveFrameStats still = selective.update(a.scene, a.arrays, a.buffers, false);
    EXPECT_EQ(still.changedPilots, 0u);
    EXPECT_TRUE(selective.markedGroups().empty());
    const SelectiveFrameStats moved = selective.update(b.scene, b.arrays, b.buffers, false);
    const std::set<uint32_t> marked(selective.markedGroups().begin(), selective.markedGroups().end());
    EXPECT_EQ(marked, expected);
    EXPECT_EQ(moved.changedPilots, expected.size());
}

// The per-frame budget holds (pilots included) and the statistics count what was traced. Pilots
// only (no tracks): changed pilots mark whole groups, retraced by their count.
TEST_F(SelectivePhoton, BudgetAndStatistics) {
    GpuSceneData a(boxScene({-1.5f, 0.0f, -0.5f}));
    GpuSceneData b(boxScene({0.5f, 0.0f, -0.5f}));
    const uint32_t groupPaths = kPaths / kGroups;
    const uint32_t budget = kGroups + 5 * groupPaths + groupPaths / 2;
    SelectiveSettings pilotsOnly = settings(budget);
    pilotsOnly.trackPaths = false;
    SelectivePhotonUpdate selective(test::gpu(), pilotsOnly);
    const SelectiveFrameStats first = selective.update(a.scene, a.arrays, a.buffers, false);
    EXPECT_TRUE(first.full);
    EXPECT_EQ(first.photonPathsTraced, kPaths);
    const SelectiveFrameStats s = selective.update(b.scene, b.arrays, b.buffers, false);
    EXPECT_FALSE(s.full);
    EXPECT_LE(s.photonPathsTraced, budget);
    EXPECT_EQ(s.pilotsTraced, kGroups);
    EXPECT_EQ(s.groupsRetraced, 5u);
    EXPECT_EQ(s.groupsRetraced, selective.retracedGroups().size());
    EXPECT_EQ(s.photonPathsTraced, kGroups + s.groupsRetraced * groupPaths);
    // Marked groups first (4 of the 5: one group's room is kept for the round-robin refresh).
    ASSERT_GT(selective.markedGroups().size(), 4u);
    const std::set<uint32_t> marked(selective.markedGroups().begin(), selective.markedGroups().end());
    for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(marked.count(selective.retracedGroups()[i]));
    const std::set<uint32_t> retraced(selective.retracedGroups().begin(), selective.retracedGroups().end());
    size_t pending = 0;
    for (uint32_t g : marked) pending += retraced.count(g) ? 0 : 1;
    EXPECT_EQ(s.groupsPending, pending);
}

// The batched retrace (every group of a frame in one dispatch through a path list) writes the same
// slots as one strided dispatch per group, bit for bit, frame after frame (marked and round-robin
// groups, with the box moving back and forth).
TEST_F(SelectivePhoton, BatchedRetraceEqualsPerGroupRetrace) {
    GpuSceneData a(boxScene({-1.5f, 0.0f, -0.5f}));
    GpuSceneData b(boxScene({0.5f, 0.0f, -0.5f}));
    SelectiveSettings perGroupSettings = settings(kGroups + 12 * 16);
    perGroupSettings.batched = false;
    SelectivePhotonUpdate batched(test::gpu(), settings(kGroups + 12 * 16)), perGroup(test::gpu(), perGroupSettings);
    for (int frame = 0; frame < 4; ++frame) {
        const GpuSceneData& s = frame % 2 == 0 ? a : b;
        const SelectiveFrameStats x = batched.update(s.scene, s.arrays, s.buffers, false);
        const SelectiveFrameStats y = perGroup.update(s.scene, s.arrays, s.buffers, false);
        EXPECT_EQ(batched.retracedGroups(), perGroup.retracedGroups()) << "frame " << frame;
        EXPECT_EQ(x.photonPathsTraced, y.photonPathsTraced);
        if (frame > 0) {
            EXPECT_GT(x.photonPathsTraced, kGroups + 3 * 16u);
            EXPECT_GT(x.stalePathsFound, 0u);  // the box is static geometry: every path is suspect
        }
        EXPECT_TRUE(samePhotons(batched.downloadSlots(), perGroup.downloadSlots())) << "frame " << frame;
    }
}

// The persistent slots are a segmented array (as many paths as memory holds, not one storage
// buffer's worth) traced a chunk of paths at a time: slots split into buffers of 128 photons and
// traced 500 paths at a time (per group: 5) equal the one-buffer slots bit for bit, frame after
// frame; maps built from them 500 paths at a time, with importance deposition too, equal the maps
// built in one go.
TEST_F(SelectivePhoton, SlotsSplitOverBuffersAndChunksEqualOneBuffer) {
    GpuSceneData a(boxScene({-1.5f, 0.0f, -0.5f}));
    GpuSceneData b(boxScene({0.5f, 0.0f, -0.5f}));
    const uint32_t budget = kGroups + 40 * 16;  // the pilots and 40 groups: 640 paths, two chunks
    SelectiveSettings split = settings(budget);
    split.segmentShift = 7;
    split.chunkPaths = 500;
    SelectiveSettings splitPerGroup = split;
    splitPerGroup.batched = false;
    splitPerGroup.chunkPaths = 5;
    SelectivePhotonUpdate whole(test::gpu(), settings(budget)), chunked(test::gpu(), split),
        perGroup(test::gpu(), splitPerGroup);
    EXPECT_EQ(whole.slots().segmentCount(), 1u);
    EXPECT_EQ(chunked.slots().segmentCount(), (kPaths * kDeposits + 127) / 128);
    EXPECT_EQ(chunked.tracks().segmentCount(), (kPaths + 127) / 128);
    for (int frame = 0; frame < 3; ++frame) {
        const GpuSceneData& s = frame % 2 == 0 ? a : b;
        const SelectiveFrameStats traced = whole.update(s.scene, s.arrays, s.buffers, false);
        chunked.update(s.scene, s.arrays, s.buffers, false);
        perGroup.update(s.scene, s.arrays, s.buffers, false);
        if (frame > 0) {
            EXPECT_GT(traced.photonPathsTraced, 500u);  // more than one chunk
        }
        EXPECT_EQ(chunked.retracedGroups(), whole.retracedGroups()) << "frame " << frame;
        for (uint32_t path = 0; path < kPaths; ++path) ASSERT_EQ(chunked.stale(path), whole.stale(path)) << path;
        const std::vector<gpu::GpuPhoton> expected = whole.downloadSlots();
        EXPECT_TRUE(samePhotons(chunked.downloadSlots(), expected)) << "frame " << frame;
        EXPECT_TRUE(samePhotons(perGroup.downloadSlots(), expected)) << "frame " << frame;
    }

    ImportonSettings importonSettings;
    importonSettings.paths = 1u << 12;
    const ImportonMap importons(test::gpu(), a.arrays, a.buffers, makeGpuCamera(chooseCamera(a.scene, -1), 32, 32), 32,
                                32, importonSettings);
    for (const uint32_t mode : {gpu::kDepositAll, gpu::kDepositImportance}) {
        SCOPED_TRACE(mode);
        PhotonMapSettings ms;
        ms.paths = kPaths;
        ms.maxDeposits = kDeposits;
        ms.seed = 7;
        ms.deposit.mode = mode;
        ms.deposit.importons = &importons;
        PhotonMap oneGo(test::gpu(), a.scene, a.arrays, a.buffers, ms);
        const PhotonMapStats x = oneGo.buildFromSlots(whole.slots(), 0);
        ms.chunkPaths = 500;
        ms.segmentShift = 7;
        PhotonMap inChunks(test::gpu(), a.scene, a.arrays, a.buffers, ms);
        const PhotonMapStats y = inChunks.buildFromSlots(chunked.slots(), 0);
        EXPECT_GT(y.stored, 1000u);
        EXPECT_EQ(y.stored, x.stored);
        EXPECT_EQ(y.candidates, x.candidates);
        if (mode == gpu::kDepositImportance) {
            EXPECT_LT(y.stored, y.candidates) << "the decision drops photons";
        }
        EXPECT_TRUE(samePhotons(inChunks.downloadPhotons(), oneGo.downloadPhotons()));
    }
}

}  // namespace
}  // namespace vkp
