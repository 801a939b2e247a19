// Small renders (64x64) of every shipped scene on lavapipe: finite, reproducible bit for bit with
// the same seed, and with a mean radiance that matches a stored high-sample reference
// (tests/data/reference_means.json, made by scripts/make_reference_means.sh) within statistical
// bounds estimated from independent seeds.
#include <cmath>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/estimators.h"
#include "support/gpu_test_support.h"
#include "image/image.h"
#include "image/metrics.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/small_frame.h"

namespace vkp {
namespace {

constexpr uint32_t kSize = 64;

RenderResult renderScene(Renderer& renderer, uint32_t spp, uint32_t seed) {
    FrameSettings s = test::smallFrame(kSize, spp, seed);
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
    std::array<std::vector<double>, 3> channelMeans;
    for (int seed = 0; seed < kSeeds; ++seed) {
        const RenderResult r = renderScene(renderer, 32, 100 + seed);
        EXPECT_TRUE(allFinite(r.image));
        EXPECT_EQ(r.stats.get<uint64_t>("counters.nonFiniteSamples"), 0u);
        const auto m = meanRadiance(r.image);
        for (int k = 0; k < 3; ++k) channelMeans[k].push_back(m[k]);
    }
    // 5 standard errors (t-distribution, 5 dof, ~0.4% two-sided) plus 1% for the reference's own noise.
    for (int k = 0; k < 3; ++k)
        test::expectAgrees(test::estimate(channelMeans[k]), reference[k], 5.0, 0.01,
                           name + " channel " + std::to_string(k));
}

// Next-event estimation with MIS and pure BSDF sampling estimate the same integral: their means
// must agree within statistical bounds (this catches visibility and pdf bugs in light sampling).
TEST_P(SceneRender, NextEventEstimationAgreesWithBsdfSampling) {
    const std::string name = GetParam();
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/" + name + ".gltf");
    Renderer renderer(test::gpu(), scene);
    constexpr int kSeeds = 6;
    std::array<std::vector<double>, 2> means;  // next-event estimation, BSDF sampling alone
    for (int mode = 0; mode < 2; ++mode)
        for (int seed = 0; seed < kSeeds; ++seed) {
            FrameSettings s = test::smallFrame(32, 64, 200 + seed);
            s.maxDepth = 2;
            s.nextEventEstimation = mode == 0;
            means[mode].push_back(meanValue(renderer.render<PathIntegrator>(s).image));
        }
    test::expectAgree(test::estimate(means[0]), test::estimate(means[1]), 5.0, 0.005,
                      name + ": NEE against BSDF sampling");
}

INSTANTIATE_TEST_SUITE_P(Shipped, SceneRender, ::testing::Values("cornell-box", "cornell-ceiling", "cornell-glass"),
                         [](const auto& info) {
                             std::string n = info.param;
                             for (char& ch : n) if (ch == '-') ch = '_';
                             return n;
                         });

}  // namespace
}  // namespace vkp
