// Small renders (64x64) of every shipped scene on lavapipe: finite, reproducible bit for bit with
// the same seed, and with a mean radiance that matches a stored high-sample reference
// (tests/data/reference_means.json, made by scripts/make_reference_means.sh) within statistical
// bounds estimated from independent seeds.
#include <cmath>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gpu_test_support.h"
#include "image/image.h"
#include "image/metrics.h"
#include "render/integrators/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"

namespace vkp {
namespace {

constexpr uint32_t kSize = 64;

RenderResult renderScene(Renderer& renderer, uint32_t spp, uint32_t seed) {
    FrameSettings s;
    s.width = kSize;
    s.height = kSize;
    s.samplesPerPixel = spp;
    s.seed = seed;
    return renderer.render<PathIntegrator>(s);
}

class SceneRender : public test::GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(SceneRender, FiniteReproducibleAndMatchesReferenceMean) {
    const std::string name = GetParam();
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/" + name + ".gltf");
    Renderer renderer(test::gpu(), scene);

    // Reproducible: the same seed gives the same bits; another seed gives another image.
    const RenderResult a = renderScene(renderer, 4, 7);
    const RenderResult b = renderScene(renderer, 4, 7);
    const RenderResult c = renderScene(renderer, 4, 8);
    ASSERT_EQ(a.image.pixels.size(), b.image.pixels.size());
    EXPECT_EQ(std::memcmp(a.image.pixels.data(), b.image.pixels.data(), a.image.pixels.size() * sizeof(float)), 0);
    EXPECT_NE(std::memcmp(a.image.pixels.data(), c.image.pixels.data(), a.image.pixels.size() * sizeof(float)), 0);

    // Mean radiance over independent seeds against the reference.
    std::ifstream in(std::string(VKPHOTON_TEST_DATA) + "/reference_means.json");
    ASSERT_TRUE(in) << "missing tests/data/reference_means.json";
    const auto reference = nlohmann::json::parse(in).at(name).get<std::array<double, 3>>();
    constexpr int kSeeds = 6;
    std::array<double, 3> sum{0, 0, 0}, sumSq{0, 0, 0};
    for (int seed = 0; seed < kSeeds; ++seed) {
        const RenderResult r = renderScene(renderer, 32, 100 + seed);
        EXPECT_TRUE(allFinite(r.image));
        EXPECT_EQ(r.stats.get<uint64_t>("counters.nonFiniteSamples"), 0u);
        const auto m = meanRadiance(r.image);
        for (int k = 0; k < 3; ++k) { sum[k] += m[k]; sumSq[k] += m[k] * m[k]; }
    }
    for (int k = 0; k < 3; ++k) {
        const double mean = sum[k] / kSeeds;
        const double variance = std::max(0.0, (sumSq[k] - kSeeds * mean * mean) / (kSeeds - 1));
        const double standardError = std::sqrt(variance / kSeeds);
        // 5 standard errors (t-distribution, 5 dof, ~0.4% two-sided) plus 1% for the reference's own noise.
        const double bound = 5.0 * standardError + 0.01 * reference[k];
        EXPECT_NEAR(mean, reference[k], bound) << name << " channel " << k << " (standard error " << standardError << ")";
    }
}

// Next-event estimation with MIS and pure BSDF sampling estimate the same integral: their means
// must agree within statistical bounds (this catches visibility and pdf bugs in light sampling).
TEST_P(SceneRender, NextEventEstimationAgreesWithBsdfSampling) {
    const std::string name = GetParam();
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/" + name + ".gltf");
    Renderer renderer(test::gpu(), scene);
    constexpr int kSeeds = 6;
    std::array<double, 2> sum{0, 0}, sumSq{0, 0};
    for (int mode = 0; mode < 2; ++mode)
        for (int seed = 0; seed < kSeeds; ++seed) {
            FrameSettings s;
            s.width = 32;
            s.height = 32;
            s.samplesPerPixel = 64;
            s.seed = 200 + seed;
            s.maxDepth = 2;
            s.nextEventEstimation = mode == 0;
            const RenderResult r = renderer.render<PathIntegrator>(s);
            const double m = meanValue(r.image);
            sum[mode] += m;
            sumSq[mode] += m * m;
        }
    double se2 = 0.0;
    std::array<double, 2> mean{};
    for (int mode = 0; mode < 2; ++mode) {
        mean[mode] = sum[mode] / kSeeds;
        se2 += std::max(0.0, (sumSq[mode] - kSeeds * mean[mode] * mean[mode]) / (kSeeds - 1)) / kSeeds;
    }
    EXPECT_NEAR(mean[0], mean[1], 5.0 * std::sqrt(se2) + 0.005 * mean[1])
        << name << ": NEE " << mean[0] << " vs BSDF sampling " << mean[1];
}

INSTANTIATE_TEST_SUITE_P(Shipped, SceneRender, ::testing::Values("cornell-box", "cornell-ceiling", "cornell-glass"),
                         [](const auto& info) {
                             std::string n = info.param;
                             for (char& ch : n) if (ch == '-') ch = '_';
                             return n;
                         });

}  // namespace
}  // namespace vkp
