// Final gathers importance-sampled from the photons (--gather-guide, docs/photon-mapping.md):
// the mixture of the guiding grid and the BSDF, weighted by the mixture density, estimates what
// BSDF-sampled gathers estimate, so its mean agrees with theirs and with the path tracer's on a
// room lit only indirectly, and a furnace reads its closed form at any mixture.
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/metrics.h"
#include "photon/photon_integrator.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "support/estimators.h"
#include "support/gpu_test_support.h"
#include "support/small_frame.h"
#include "support/test_scenes.h"

namespace vkp {
namespace {

class GuidedGatherTest : public test::GpuTest {};

PhotonIntegratorSettings gatherSettings(float guide) {
    PhotonIntegratorSettings p;
    p.globalPaths = 40000;
    p.causticPaths = 0;  // nothing specular in the scenes below
    p.gatherRays = 2;
    p.gatherGuide = guide;
    return p;
}

// Mean luminance over seeds: each seed a new photon map and new camera samples.
template <typename Render> test::Estimate meanOverSeeds(int seeds, Render render) {
    std::vector<double> means;
    for (int i = 0; i < seeds; ++i) means.push_back(meanLuminance(render(100u + 17u * uint32_t(i))));
    return test::estimate(means);
}

// cornell-ceiling: the light faces the ceiling, so everything but the ceiling's patch is lit
// indirectly, the case the guide is for. The guided gathers (the grid alone where it covers the
// normal, and half and half) read the BSDF-sampled gathers' mean (same photon maps), and both
// read the path tracer's within the photon map's small density-estimation bias.
TEST_F(GuidedGatherTest, MeanAgreesWithBsdfSampledGathersAndThePathTracer) {
    const Scene scene = test::shippedScene("cornell-ceiling");
    Renderer renderer(test::gpu(), scene);
    constexpr int kSeeds = 4;
    const auto photon = [&](float guide) {
        return meanOverSeeds(kSeeds, [&](uint32_t seed) {
            RenderResult r = renderer.render<PhotonIntegrator>(test::smallFrame(16, 4, seed), gatherSettings(guide));
            EXPECT_EQ(r.stats.get<double>("settings.photon.gatherGuide"), double(guide));
            return r.image;
        });
    };
    const test::Estimate bsdf = photon(0.0f);
    const test::Estimate half = photon(0.5f);
    const test::Estimate grid = photon(1.0f);
    const test::Estimate path = meanOverSeeds(kSeeds, [&](uint32_t seed) {
        return renderer.render<PathIntegrator>(test::smallFrame(16, 64, seed)).image;
    });
    std::printf("cornell-ceiling mean: BSDF gathers %.4f +- %.4f, guided 0.5 %.4f +- %.4f, guided 1 %.4f +- %.4f, "
                "path tracer %.4f +- %.4f\n",
                bsdf.mean, bsdf.standardError, half.mean, half.standardError, grid.mean, grid.standardError, path.mean,
                path.standardError);
    test::expectAgree(half, bsdf, 4.0, 0.01, "guided gathers (mix 0.5) against BSDF-sampled ones");
    test::expectAgree(grid, bsdf, 4.0, 0.01, "guided gathers (mix 1) against BSDF-sampled ones");
    test::expectAgree(half, path, 4.0, 0.03, "guided gathers against the path tracer");
}

// The furnace (a closed Lambert box of albedo 0.5 emitting 0.5 everywhere: radiance 1), read with
// a k-nearest estimate at every gather hit (radiance photons' boundary bias left out).
TEST_F(GuidedGatherTest, FurnaceReadsItsClosedForm) {
    const Scene scene = test::furnaceScene(0.5f, 0.5f);
    Renderer renderer(test::gpu(), scene);
    FrameSettings s = test::smallFrame(16, 16, 3);
    s.maxDepth = 24;
    for (const float guide : {0.0f, 0.5f, 1.0f}) {
        PhotonIntegratorSettings p = gatherSettings(guide);
        p.globalPaths = 100000;
        p.radiancePhotonStride = 0;
        const double mean = meanLuminance(renderer.render<PhotonIntegrator>(s, p).image);
        std::printf("furnace, guided gathers (mix %.1f): %.4f\n", guide, mean);
        EXPECT_NEAR(mean, 1.0, 0.01) << "mix " << guide;
    }
}

}  // namespace
}  // namespace vkp
