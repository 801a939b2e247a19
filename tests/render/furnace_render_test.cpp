// Furnace tests: a closed Lambertian enclosure with uniform emission Le and albedo a has radiance
// Le / (1 - a) everywhere, whatever the path tracer's sampling strategy.
#include <cmath>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "image/image.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "support/test_scenes.h"
#include "support/small_frame.h"

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

}  // namespace
}  // namespace vkp
