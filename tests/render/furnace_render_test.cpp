// Furnace tests: a closed Lambertian enclosure with uniform emission Le and albedo a has radiance
// Le / (1 - a) everywhere, whatever the path tracer's sampling strategy. Every path's throughput
// after n bounces is a^n there, so Russian roulette's expected path length has a closed form too.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "guiding/guided_integrator.h"
#include "image/image.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "support/test_scenes.h"
#include "support/small_frame.h"
#include "shared/kernels/path_trace.glsl"

namespace vkp {
namespace {

class Furnace : public test::GpuTest {};

double renderMean(const Scene& scene, bool nee, uint32_t spp, uint32_t seed) {
    Renderer renderer(test::gpu(), scene);
    FrameSettings s = test::smallFrame(32, spp, seed);
    s.maxDepth = 96;
    s.nextEventEstimation = nee;
    const RenderResult r = renderer.render<PathIntegrator>(s);
    EXPECT_EQ(r.stats.get<uint64_t>("counters.nonFiniteSamples"), 0u);
    double sum = 0.0;
    for (float v : r.image.pixels) {
        EXPECT_TRUE(std::isfinite(v));
        sum += v;
    }
    return sum / r.image.pixels.size();
}

TEST_F(Furnace, HalfAlbedoWithNextEventEstimation) {
    const double mean = renderMean(test::furnaceScene(0.5f, 0.5f), true, 64, 1);
    EXPECT_NEAR(mean, 1.0, 0.01);
}

TEST_F(Furnace, HalfAlbedoBsdfSamplingOnly) {
    const double mean = renderMean(test::furnaceScene(0.5f, 0.5f), false, 64, 2);
    EXPECT_NEAR(mean, 1.0, 0.01);
}

TEST_F(Furnace, HighAlbedo) {
    const double mean = renderMean(test::furnaceScene(0.8f, 0.2f), true, 64, 3);
    EXPECT_NEAR(mean, 1.0, 0.01);
}

// Expected rays per camera path in a closed Lambert enclosure of albedo a: the throughput after
// sampling at vertex d is a^(d+1) divided by the survival probabilities so far, the roulette
// (gpu::rouletteSurvival) decides whether the next ray is traced, and the ray to vertex maxDepth
// is the last.
double expectedSegmentsPerPath(double albedo, uint32_t maxDepth) {
    double reached = 1.0, throughput = 1.0, segments = 0.0;
    for (uint32_t depth = 0; depth <= maxDepth; ++depth) {
        segments += reached;  // the ray that found vertex `depth`
        throughput *= albedo;
        const double survive = gpu::rouletteSurvival(depth, float(throughput));
        reached *= survive;
        throughput /= survive;
    }
    return segments;
}

// Russian roulette ends paths as documented (shared/kernels/path_trace.glsl), and the guided
// tracer's roulette sees the throughput BSDF sampling would have carried, whatever the guide's
// densities: its paths are as long as the path tracer's. At albedo 0.8 the closed form is 10.4 rays
// per path (5.9 with a roulette gain of 1); the guided tracer's averaged 9.4 when its roulette read
// the guided throughput.
TEST_F(Furnace, RussianRouletteGivesTheExpectedPathLength) {
    const float albedo = 0.8f;
    const Scene scene = test::furnaceScene(albedo, 1.0f - albedo);
    Renderer renderer(test::gpu(), scene);
    FrameSettings s = test::smallFrame(32, 32, 4);
    const double expected = expectedSegmentsPerPath(albedo, s.maxDepth);
    GuideSettings guide;
    guide.photons = 30000;
    for (const bool guided : {false, true}) {
        const RenderResult r = guided ? renderer.render<GuidedIntegrator>(s, guide) : renderer.render<PathIntegrator>(s);
        const double perPath = double(r.stats.get<uint64_t>("counters.pathSegments")) /
                               double(r.stats.get<uint64_t>("counters.cameraPaths"));
        std::printf("furnace, albedo %.1f, %s: %.3f rays per path, expected %.3f\n", albedo,
                    guided ? "guided" : "path", perPath, expected);
        EXPECT_NEAR(perPath, expected, 0.01 * expected) << (guided ? "guided" : "path");
    }
}

}  // namespace
}  // namespace vkp
