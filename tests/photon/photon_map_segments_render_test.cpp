// Photon maps split over several buffers (vk/segmented_buffer.h): a map, its grid and the gathers
// over them are the same whether each array is one buffer or many (PhotonMapSettings::segmentShift
// lowered so small maps span dozens of buffers), renders of every photon estimate are bit for bit
// the same, a real map past lavapipe's 4 M photons per storage buffer loses no photon, and a map
// the device cannot hold is a RuntimeError (exit 1), not a crash.
#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "image/image.h"
#include "photon/photon_integrator.h"
#include "photon/progressive_photon_integrator.h"
#include "render/frame.h"
#include "photon/importon_map.h"
#include "photon/photon_map.h"
#include "render/renderer.h"
#include "shared/photon.glsl"
#include "shared/photon_grid.glsl"
#include "shaders/test_kernels.glsl"
#include "support/test_scenes.h"
#include "util/errors.h"
#include "vk/kernel.h"
#include "vk/segmented_buffer.h"
#include "support/small_frame.h"

namespace vkp {
namespace {

class PhotonMapSegmentsTest : public test::GpuTest {};

constexpr uint32_t kSmallSegmentShift = 10;  // 1024 photons per buffer

bool samePhotons(const std::vector<gpu::GpuPhoton>& a, const std::vector<gpu::GpuPhoton>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(gpu::GpuPhoton)) == 0;
}

TEST_F(PhotonMapSegmentsTest, SplitMapAndGridEqualOneBuffer) {
    const Scene scene = test::shippedScene("cornell-glass");
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(test::gpu(), arrays);
    PhotonMapSettings settings;
    settings.paths = 30000;
    settings.seed = 5;
    settings.chunkPaths = 7001;  // the map grows chunk by chunk
    PhotonMap whole(test::gpu(), scene, arrays, buffers, settings);
    settings.segmentShift = kSmallSegmentShift;
    PhotonMap split(test::gpu(), scene, arrays, buffers, settings);
    const PhotonMapStats a = whole.build(0);
    const PhotonMapStats b = split.build(0);
    ASSERT_GT(a.stored, 20u << kSmallSegmentShift);  // dozens of buffers
    EXPECT_EQ(b.stored, a.stored);
    EXPECT_EQ(b.dropped, 0u);
    EXPECT_EQ(split.segmentPhotons(), 1u << kSmallSegmentShift);
    EXPECT_TRUE(samePhotons(split.downloadPhotons(), whole.downloadPhotons()));
    EXPECT_EQ(split.grid().cellStart().download<uint32_t>(), whole.grid().cellStart().download<uint32_t>());
    EXPECT_TRUE(samePhotons(split.grid().downloadPhotons(), whole.grid().downloadPhotons()));
    // Memory: the split map grows with the photons stored (segments of 1024), the whole one holds
    // a buffer for every slot its paths could fill; both at least the photons and their grid.
    EXPECT_EQ(b.bytes, split.bytes());
    EXPECT_GE(b.bytes, b.stored * (2 * sizeof(gpu::GpuPhoton) + sizeof(uint32_t)));
    EXPECT_LT(b.bytes, a.bytes);
}

TEST_F(PhotonMapSegmentsTest, RendersFromSplitMapsEqualOneBuffer) {
    const Scene scene = test::shippedScene("cornell-glass");
    Renderer renderer(test::gpu(), scene);
    FrameSettings s = test::smallFrame(32, 2, 4);
    PhotonIntegratorSettings p;
    p.globalPaths = 20000;
    p.causticPaths = 20000;
    // Final gather with radiance photons, then k nearest at every gather hit, then progressive.
    for (int mode = 0; mode < 3; ++mode) {
        SCOPED_TRACE(mode);
        p.radiancePhotonStride = mode == 1 ? 0 : 4;
        auto render = [&](uint32_t shift) {
            PhotonIntegratorSettings q = p;
            q.mapSegmentShift = shift;
            return mode == 2 ? renderer.render<ProgressivePhotonIntegrator>(s, q) : renderer.render<PhotonIntegrator>(s, q);
        };
        const RenderResult whole = render(0);
        const RenderResult split = render(kSmallSegmentShift);
        ASSERT_EQ(split.image.pixels.size(), whole.image.pixels.size());
        EXPECT_EQ(std::memcmp(split.image.pixels.data(), whole.image.pixels.data(),
                              whole.image.pixels.size() * sizeof(whole.image.pixels[0])),
                  0);
        EXPECT_GT(split.stats.get<double>("photons.mapBytes"), 0.0);
    }
}

double totalRelativePower(const std::vector<gpu::GpuPhoton>& photons) {
    double sum = 0.0;
    for (const gpu::GpuPhoton& p : photons) {
        const glm::vec3 power = gpu::photonRelativePower(p);
        sum += double(power.x) + power.y + power.z;
    }
    return sum;
}

// Density control's redistribution sums (3 words a map photon) are a segmented array as well: split
// into buffers of 1024 words, the map equals the one-buffer map bit for bit, and rejected photons'
// power reaches their neighbours (the map's flux stays the traced flux; dropped sums would lose it).
TEST_F(PhotonMapSegmentsTest, DensityControlSplitEqualsOneBuffer) {
    const Scene scene = test::shippedScene("cornell-box");
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(test::gpu(), arrays);
    ImportonSettings importonSettings;
    importonSettings.paths = 1u << 13;
    const ImportonMap importons(test::gpu(), arrays, buffers, makeGpuCamera(chooseCamera(scene, -1), 32, 32), 32, 32,
                                importonSettings);
    PhotonMapSettings settings;
    settings.paths = 30000;
    settings.seed = 5;
    PhotonMap all(test::gpu(), scene, arrays, buffers, settings);
    const PhotonMapStats allStats = all.build(0);
    settings.deposit.mode = gpu::kDepositDensity;
    settings.deposit.importons = &importons;
    settings.deposit.densityAccuracy = 1e3f;
    settings.deposit.rounds = 4;
    PhotonMap whole(test::gpu(), scene, arrays, buffers, settings);
    settings.segmentShift = kSmallSegmentShift;
    PhotonMap split(test::gpu(), scene, arrays, buffers, settings);
    const PhotonMapStats a = whole.build(0);
    const PhotonMapStats b = split.build(0);
    ASSERT_LT(a.stored, a.candidates / 2) << "density control rejects photons";
    ASSERT_GT(a.stored, 4u << kSmallSegmentShift) << "the sums span a dozen buffers";
    EXPECT_EQ(b.stored, a.stored);
    const std::vector<gpu::GpuPhoton> photons = split.downloadPhotons();
    EXPECT_TRUE(samePhotons(photons, whole.downloadPhotons()));
    // The memory reported holds the sums too (12 bytes a photon beside the map's and grid's 68).
    EXPECT_GE(b.bytes, b.stored * (2 * sizeof(gpu::GpuPhoton) + 4 * sizeof(uint32_t)));
    const double traced = totalRelativePower(all.downloadPhotons());
    EXPECT_NEAR(totalRelativePower(photons), traced, 0.01 * traced);
}

// A real map past lavapipe's maxStorageBufferRange / 32 = 4 M photons (2^22): every photon is
// stored (none dropped) and lands in the grid, in its bucket, across the buffers' boundary.
TEST_F(PhotonMapSegmentsTest, MapPastFourMillionPhotonsKeepsThemAll) {
    const Scene scene = test::shippedScene("cornell-glass");
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(test::gpu(), arrays);
    PhotonMapSettings settings;
    settings.paths = 2700000;  // about 1.64 photons per path on cornell-glass: 4.4 M photons
    settings.seed = 1;
    settings.cellSize = 0.02f;
    PhotonMap map(test::gpu(), scene, arrays, buffers, settings);
    const PhotonMapStats stats = map.build(0);
    const uint64_t oneBuffer = test::gpu().properties().limits.maxStorageBufferRange / sizeof(gpu::GpuPhoton);
    if (stats.stored <= oneBuffer)  // e.g. NVIDIA: 4 GiB, 134 M photons in one buffer
        GTEST_SKIP() << "this device stores " << oneBuffer << " photons in one buffer; the test's map has " << stats.stored;
    EXPECT_EQ(stats.dropped, 0u);
    EXPECT_EQ(stats.stored, stats.traced.storedCaustic + stats.traced.storedGlobal + stats.traced.storedPrimary);
    EXPECT_GE(stats.bytes, stats.stored * (2 * sizeof(gpu::GpuPhoton) + sizeof(uint32_t)));
    const auto starts = map.grid().cellStart().download<uint32_t>();
    const uint32_t table = map.grid().tableSize();
    ASSERT_EQ(starts[table], stats.stored);
    const auto sorted = map.grid().downloadPhotons();
    ASSERT_EQ(sorted.size(), stats.stored);
    // The buckets around the first buffer's end hold their own photons only.
    const uint32_t boundary = static_cast<uint32_t>(oneBuffer);
    const uint32_t bucket = static_cast<uint32_t>(std::upper_bound(starts.begin(), starts.end(), boundary) - starts.begin()) - 1;
    const float inv = 1.0f / settings.cellSize;
    for (uint32_t b = bucket > 2 ? bucket - 2 : 0; b < std::min(table, bucket + 3); ++b)
        for (uint32_t i = starts[b]; i < starts[b + 1]; ++i)
            ASSERT_EQ(gpu::gridHash(gpu::gridCell(sorted[i].position, inv), table - 1), b) << "photon " << i;
    // The grid holds the map's photons, each once.
    auto key = [](const gpu::GpuPhoton& p) {
        uint64_t k[4];
        std::memcpy(k, &p, sizeof(p));
        return std::array<uint64_t, 4>{k[0], k[1], k[2], k[3]};
    };
    std::vector<std::array<uint64_t, 4>> inMap, inGrid;
    for (const auto& p : map.downloadPhotons()) inMap.push_back(key(p));
    for (const auto& p : sorted) inGrid.push_back(key(p));
    std::sort(inMap.begin(), inMap.end());
    std::sort(inGrid.begin(), inGrid.end());
    EXPECT_TRUE(inMap == inGrid);
}

// Kernels are compiled twice (shaders/common/segmented_arrays.glsl): a dispatch whose segmented arrays all have
// one segment runs the form that indexes segment 0 directly, any other the form that reads the
// table; the choice follows the array as it grows, and both read and write the same elements.
TEST_F(PhotonMapSegmentsTest, KernelsOfOneSegmentArraysIndexItDirectly) {
    vk::Context& context = test::gpu();
    constexpr uint32_t kCount = 3000;
    vk::SegmentedBuffer array(context, "segmented test array", sizeof(uint32_t), kCount, kSmallSegmentShift);
    vk::Buffer out(context, "segmented test outputs", (kCount + 1) * sizeof(uint32_t), vk::kStorageUsage);
    vk::Kernel<gpu::SegmentedTestKernel> kernel(context);
    kernel.bind(gpu::kSegmentedTestArrayBinding, array.table());
    kernel.bind(gpu::kSegmentedTestOutputBinding, out);
    std::vector<uint32_t> values(kCount);
    for (uint32_t i = 0; i < kCount; ++i) values[i] = 7 * i + 3;
    // 1024 elements (one segment), then all 3000 (three): the same kernel, bound once.
    for (uint32_t count : {1u << kSmallSegmentShift, kCount}) {
        SCOPED_TRACE(count);
        array.upload(values.data(), 0, count);
        const bool oneSegment = array.segmentCount() == 1;
        EXPECT_EQ(oneSegment, count <= (1u << kSmallSegmentShift));
        out.upload(std::vector<uint32_t>(kCount + 1, 0xffffffffu));
        context.submitAndWait([&](VkCommandBuffer cmd) {
            kernel.record(cmd, count, gpu::SegmentedTestParams{count, 0, 0, 0});
            vk::computeToHostBarrier(cmd);
        });
        const auto outputs = out.download<uint32_t>();
        EXPECT_EQ(outputs[0], oneSegment ? 1u : 0u);
        const auto stored = array.download<uint32_t>(count);
        for (uint32_t i = 0; i < count; ++i) {
            ASSERT_EQ(outputs[1 + i], values[i]) << "element " << i;
            ASSERT_EQ(stored[i], values[i] + 1) << "element " << i;
        }
    }
}

TEST_F(PhotonMapSegmentsTest, MoreThanTheDeviceHoldsIsARuntimeError) {
    vk::Context& context = test::gpu();
    const uint64_t elements = (uint64_t(1) << 40) / sizeof(gpu::GpuPhoton);  // 1 TiB of photons
    vk::SegmentedBuffer huge(context, "test photon map", sizeof(gpu::GpuPhoton), elements);
    EXPECT_THROW(huge.reserve(elements), RuntimeError);
    EXPECT_EQ(huge.allocated(), 0u);
    huge.reserve(1000);  // what fits still does, about what was asked for
    EXPECT_GE(huge.allocated(), 1000u);
    EXPECT_LT(huge.allocated(), uint64_t(1) << huge.segmentShift());
}

}  // namespace
}  // namespace vkp
