// The photon hash grid: the GPU prefix sum against the host, the grid's structure (every photon
// in its bucket, the map's photons and no others, identical on a rebuild), and its gathers —
// fixed radius with the cone filter and k nearest — against brute force over the same photons.
#include <algorithm>
#include <cstring>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "photon/photon_grid.h"
#include "photon/radiance_photons.h"
#include "passes/prefix_scan.h"
#include "shared/bsdf.glsl"
#include "shared/photon.glsl"
#include "shared/photon_estimate.glsl"
#include "shared/photon_grid.glsl"
#include "shared/sampling.glsl"
#include "shaders/test_kernels.glsl"
#include "vk/kernel.h"
#include "vk/segmented_buffer.h"

namespace vkp {
namespace {

class PhotonGridTest : public test::GpuTest {};

std::vector<uint32_t> gpuExclusiveScan(const std::vector<uint32_t>& values) {
    vk::Context& context = test::gpu();
    vk::Buffer data = vk::makeStorageBuffer(context, "scan data", values);
    PrefixScan scan(context, data, static_cast<uint32_t>(values.size()));
    context.submitAndWait([&](VkCommandBuffer cmd) {
        scan.record(cmd);
        vk::computeToHostBarrier(cmd);
    });
    auto out = data.download<uint32_t>();
    out.resize(values.size());
    return out;
}

TEST_F(PhotonGridTest, PrefixScanMatchesTheHost) {
    std::mt19937 rng(7);
    for (uint32_t n : {1u, 255u, 256u, 257u, 65536u + 3u, 3000017u}) {
        std::vector<uint32_t> values(n);
        for (auto& v : values) v = rng() % 17;
        std::vector<uint32_t> expected(n);
        std::exclusive_scan(values.begin(), values.end(), expected.begin(), 0u);
        const auto got = gpuExclusiveScan(values);
        ASSERT_EQ(got.size(), expected.size());
        size_t firstMismatch = n;
        for (size_t i = 0; i < n && firstMismatch == n; ++i)
            if (got[i] != expected[i]) firstMismatch = i;
        EXPECT_EQ(firstMismatch, n) << "n = " << n << ": first mismatch at " << firstMismatch;
    }
}

// Random photons in [0,1]^3 with a few surface normals (+y, -y, +x, a diagonal) and all flag
// combinations; one slot in eight empty. Each photon's id is kept in its lightIndex field.
std::vector<gpu::GpuPhoton> randomPhotons(uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const glm::vec3 normals[4] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, glm::normalize(glm::vec3(0.2f, 1, 0.1f))};
    const uint32_t flagChoices[4] = {gpu::kPhotonValid, gpu::kPhotonValid | gpu::kPhotonCaustic,
                                     gpu::kPhotonValid | gpu::kPhotonPrimary, gpu::kPhotonValid};
    std::vector<gpu::GpuPhoton> photons(count);
    for (uint32_t i = 0; i < count; ++i) {
        if (rng() % 8 == 0) { photons[i] = gpu::GpuPhoton{}; continue; }
        // One photon in eight in a dense blob, so some buckets hold hundreds. (More would make a
        // query visit more photons than lavapipe's loop limit allows: see docs/photon-mapping.md.)
        glm::vec3 p(unit(rng), unit(rng), unit(rng));
        if (i % 8 == 1) p = glm::vec3(0.5f) + 0.06f * (p - 0.5f);
        const glm::vec3 power(unit(rng) + 0.1f, unit(rng) + 0.1f, unit(rng) + 0.1f);
        glm::vec3 dir(unit(rng) - 0.5f, unit(rng), unit(rng) - 0.5f);
        photons[i] = gpu::makePhoton(p, power, glm::normalize(dir), normals[rng() % 4], flagChoices[rng() % 4], i);
    }
    return photons;
}

// The photons as a segmented array (what grids read), in buffers of 2^shift photons (0: the default).
vk::SegmentedBuffer photonArray(vk::Context& context, const std::vector<gpu::GpuPhoton>& photons, uint32_t shift = 0) {
    vk::SegmentedBuffer array(context, "test photons", sizeof(gpu::GpuPhoton), photons.size(), shift);
    array.upload(photons.data(), 0, photons.size());
    return array;
}

struct GatherQuery {
    glm::vec3 position;
    float radius;
    glm::vec3 normal;
    uint32_t k;
};

const glm::vec3 kTestWo = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f));  // as in photon_gather_test.comp

bool countsAt(const gpu::GpuPhoton& p, glm::vec3 n, uint32_t required, uint32_t rejected) {
    return gpu::photonSelected(gpu::photonFlags(p), required, rejected) &&
           glm::dot(gpu::decodeOctahedral(p.normal), n) > gpu::kGatherNormalCosine;
}

// In one buffer and split over 16 buffers of 1024 photons (input, sorted slots and grid photons).
class PhotonGridSegmentTest : public PhotonGridTest, public ::testing::WithParamInterface<uint32_t> {};

TEST_P(PhotonGridSegmentTest, GathersMatchBruteForce) {
    vk::Context& context = test::gpu();
    const auto photons = randomPhotons(16000, 3);
    vk::SegmentedBuffer photonBuffer = photonArray(context, photons, GetParam());
    PhotonGridSettings settings;
    settings.cellSize = 0.04f;
    settings.rejectedFlags = gpu::kPhotonPrimary;
    PhotonGrid grid(context, photonBuffer, static_cast<uint32_t>(photons.size()), settings, GetParam());
    if (GetParam()) {
        ASSERT_EQ(photonBuffer.segmentCount(), 16u);
        ASSERT_EQ(grid.photonArray().segmentCount(), 16u);
    }

    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<GatherQuery> queries(512);
    for (size_t q = 0; q < queries.size(); ++q) {
        glm::vec3 p(unit(rng), unit(rng), unit(rng));
        if (q % 2) p = glm::vec3(0.5f) + 0.05f * (p - 0.5f);  // in and around the blob
        queries[q] = {p, 0.005f + 0.12f * unit(rng), q % 5 == 0 ? glm::vec3(0, -1, 0) : glm::vec3(0, 1, 0),
                      1 + uint32_t(rng() % gpu::kMaxGatherK)};
    }
    vk::Buffer queryBuffer = vk::makeStorageBuffer(context, "queries", queries);
    vk::Buffer fixedOut(context, "fixed results", queries.size() * sizeof(glm::vec4), vk::kStorageUsage);
    constexpr uint32_t kStride = gpu::kMaxGatherK + 2;
    vk::Buffer nearestOut(context, "nearest results", queries.size() * kStride * sizeof(uint32_t), vk::kStorageUsage);
    vk::Kernel<gpu::GatherTestKernel> kernel(context);
    kernel.bind(gpu::kGatherTestQueryBinding, queryBuffer);
    kernel.bind(gpu::kGatherTestFixedBinding, fixedOut);
    kernel.bind(gpu::kGatherTestNearestBinding, nearestOut);
    kernel.bind(gpu::kGatherTestGridBinding, grid.cellStart());
    kernel.bind(gpu::kGatherTestGridBinding + 1, grid.photons());

    gpu::GatherTestParams push{};
    push.grid = grid.view(1.0f);
    gpu::BsdfParams bsdf = gpu::makeBsdfParams(glm::vec3(0.8f, 0.6f, 0.4f), 0.0f, 0.5f);
    // The test kernel binds no albedo tables (VKP_NO_BSDF_TABLES): compare the plain GGX both sides.
    bsdf.flags |= gpu::kBsdfNoEnergyCompensation;
    vk::Buffer bsdfBuffer = vk::makeStorageBuffer(context, "bsdf", std::vector<gpu::BsdfParams>{bsdf});
    kernel.bind(gpu::kGatherTestBsdfBinding, bsdfBuffer);
    push.count = static_cast<uint32_t>(queries.size());
    push.coneK = 1.1f;
    push.rejectedFlags = gpu::kPhotonPrimary;
    context.submitAndWait([&](VkCommandBuffer cmd) {
        grid.record(cmd);
        vk::computeBarrier(cmd);
        kernel.record(cmd, queries.size(), push);
        vk::computeToHostBarrier(cmd);
    });
    const auto fixed = fixedOut.download<glm::vec4>();
    const auto nearest = nearestOut.download<uint32_t>();

    size_t nonEmpty = 0, fullK = 0;
    for (size_t q = 0; q < queries.size(); ++q) {
        const GatherQuery& query = queries[q];
        glm::vec3 t, b;
        gpu::orthonormalBasis(query.normal, t, b);
        glm::vec3 sum(0.0f);
        uint32_t count = 0;
        std::vector<std::pair<float, uint32_t>> candidates;  // (squared distance, id) within the radius
        for (const auto& p : photons) {
            if (!countsAt(p, query.normal, 0, gpu::kPhotonPrimary)) continue;
            const glm::vec3 d = p.position - query.position;
            const float d2 = glm::dot(d, d);
            if (d2 < query.radius * query.radius) candidates.push_back({d2, p.lightIndex});
            if (d2 > query.radius * query.radius) continue;
            const glm::vec3 wi = gpu::toLocal(gpu::decodeOctahedral(p.direction), t, b, query.normal);
            sum += gpu::evalBsdf(bsdf, kTestWo, wi) * gpu::photonRelativePower(p) *
                   gpu::coneFilterWeight(std::sqrt(d2), query.radius, push.coneK);
            ++count;
        }
        nonEmpty += count > 0;
        EXPECT_EQ(uint32_t(fixed[q].w), count) << "query " << q;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(fixed[q][c], sum[c], 1e-4f * (1.0f + sum[c])) << "query " << q << " channel " << c;

        std::sort(candidates.begin(), candidates.end());
        const size_t expectedFound = std::min<size_t>(candidates.size(), query.k);
        const uint32_t* out = &nearest[q * kStride];
        ASSERT_EQ(out[0], expectedFound) << "query " << q;
        std::vector<uint32_t> expectedIds, gotIds(out + 2, out + 2 + expectedFound);
        for (size_t j = 0; j < expectedFound; ++j) expectedIds.push_back(candidates[j].second);
        std::sort(expectedIds.begin(), expectedIds.end());
        std::sort(gotIds.begin(), gotIds.end());
        EXPECT_EQ(gotIds, expectedIds) << "query " << q;
        float radius2;
        std::memcpy(&radius2, &out[1], sizeof(float));
        const float expectedRadius2 = expectedFound == query.k ? candidates[query.k - 1].first
                                                               : query.radius * query.radius;
        EXPECT_FLOAT_EQ(radius2, expectedRadius2) << "query " << q;
        fullK += expectedFound == query.k;
    }
    // The queries exercise both regimes: sums over many photons and radii shrunk to the k-th.
    EXPECT_GT(nonEmpty, queries.size() / 2);
    EXPECT_GT(fullK, queries.size() / 4);
}

TEST_P(PhotonGridSegmentTest, EveryMapPhotonLandsInItsBucketAndRebuildsAreIdentical) {
    vk::Context& context = test::gpu();
    const auto photons = randomPhotons(100000, 5);
    vk::SegmentedBuffer photonBuffer = photonArray(context, photons, GetParam());
    PhotonGridSettings settings;
    settings.cellSize = 0.01f;
    settings.requiredFlags = gpu::kPhotonCaustic;
    PhotonGrid grid(context, photonBuffer, static_cast<uint32_t>(photons.size()), settings, GetParam());
    auto build = [&] {
        context.submitAndWait([&](VkCommandBuffer cmd) {
            grid.record(cmd);
            vk::computeToHostBarrier(cmd);
        });
        return std::make_pair(grid.cellStart().download<uint32_t>(), grid.downloadPhotons());
    };
    const auto [starts, sorted] = build();
    std::vector<uint32_t> expectedIds;
    for (const auto& p : photons)
        if (gpu::photonSelected(gpu::photonFlags(p), gpu::kPhotonCaustic, 0)) expectedIds.push_back(p.lightIndex);
    const uint32_t total = starts[grid.tableSize()];
    ASSERT_EQ(total, expectedIds.size());
    EXPECT_EQ(grid.downloadPhotonCount(), total);
    std::vector<uint32_t> gotIds;
    const float inv = 1.0f / settings.cellSize;
    for (uint32_t bucket = 0; bucket < grid.tableSize(); ++bucket) {
        ASSERT_LE(starts[bucket], starts[bucket + 1]);
        for (uint32_t i = starts[bucket]; i < starts[bucket + 1]; ++i) {
            EXPECT_EQ(gpu::gridHash(gpu::gridCell(sorted[i].position, inv), grid.tableSize() - 1), bucket);
            if (i > starts[bucket]) {
                EXPECT_LT(sorted[i - 1].lightIndex, sorted[i].lightIndex) << "slot order";
            }
            gotIds.push_back(sorted[i].lightIndex);
        }
    }
    std::sort(gotIds.begin(), gotIds.end());
    EXPECT_EQ(gotIds, expectedIds);

    const auto [starts2, sorted2] = build();
    EXPECT_EQ(starts2, starts);
    ASSERT_EQ(sorted2.size(), sorted.size());
    EXPECT_EQ(std::memcmp(sorted2.data(), sorted.data(), total * sizeof(gpu::GpuPhoton)), 0);
}


// Radiance photons of a map, and of the same map with one more photon: the radiance photons away
// from the new photon (farther than the gather radius, not in its bucket) are the same records.
// Their choice used to be every stride-th photon in grid order, which one photon more shifted over
// the whole map: an animation's frames then flickered everywhere (docs/benchmarks.md).
TEST_F(PhotonGridTest, RadiancePhotonsChangeOnlyNearAnAddedPhoton) {
    vk::Context& context = test::gpu();
    constexpr float kCell = 0.1f, kMaxRadius = 0.05f;  // ~14 photons a cell, most buckets hold more than kStride
    constexpr uint32_t kStride = 4, kK = 16, kTable = 4096;
    std::vector<gpu::GpuPhoton> photons = randomPhotons(16000, 9);
    const glm::vec3 added(0.93f, 0.07f, 0.91f);
    auto radiance = [&](const std::vector<gpu::GpuPhoton>& input) {
        vk::SegmentedBuffer buffer = photonArray(context, input);
        PhotonGridSettings settings;
        settings.cellSize = kCell;
        settings.tableSize = kTable;
        PhotonGrid grid(context, buffer, static_cast<uint32_t>(input.size()), settings);
        context.submitAndWait([&](VkCommandBuffer cmd) {
            grid.record(cmd);
            vk::computeToHostBarrier(cmd);
        });
        RadiancePhotons rp(context, grid, grid.downloadPhotonCount(), 1.0f, kStride, kK, kMaxRadius);
        context.submitAndWait([&](VkCommandBuffer cmd) {
            rp.record(cmd);
            vk::computeToHostBarrier(cmd);
        });
        std::vector<gpu::GpuPhoton> out = rp.grid().downloadPhotons();
        std::map<uint32_t, gpu::GpuPhoton> byId;  // randomPhotons keeps a photon's id in lightIndex
        for (const auto& p : out) byId[p.lightIndex] = p;
        return std::make_pair(byId, grid.downloadPhotonCount());
    };
    const auto [before, photonsBefore] = radiance(photons);
    photons.push_back(gpu::makePhoton(added, glm::vec3(1.0f), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0), gpu::kPhotonValid,
                                      static_cast<uint32_t>(photons.size())));
    const auto [after, photonsAfter] = radiance(photons);
    ASSERT_EQ(photonsAfter, photonsBefore + 1);
    EXPECT_GT(before.size(), photonsBefore / (2 * kStride));  // about 1 in kStride, more in sparse buckets
    EXPECT_LT(before.size(), photonsBefore / 2);
    const uint32_t addedBucket = gpu::gridHash(gpu::gridCell(added, 1.0f / kCell), kTable - 1);
    auto away = [&](const gpu::GpuPhoton& p) {
        return glm::distance(p.position, added) > 2.0f * kMaxRadius &&
               gpu::gridHash(gpu::gridCell(p.position, 1.0f / kCell), kTable - 1) != addedBucket;
    };
    size_t compared = 0, differing = 0;
    for (const auto& [id, p] : before) {
        if (!away(p)) continue;
        ++compared;
        const auto it = after.find(id);
        if (it == after.end() || std::memcmp(&it->second, &p, sizeof(p)) != 0) ++differing;
    }
    for (const auto& [id, p] : after)
        if (away(p) && !before.count(id)) ++differing;
    EXPECT_GT(compared, before.size() / 2);
    EXPECT_EQ(differing, 0u) << "of " << compared << " radiance photons away from the added photon";
}

INSTANTIATE_TEST_SUITE_P(OneOrManyBuffers, PhotonGridSegmentTest, ::testing::Values(0u, 10u));

}  // namespace
}  // namespace vkp
