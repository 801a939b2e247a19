// vkphoton against another renderer: the shipped Cornell scenes with KHR_materials_specular
// specularFactor 0 on every opaque non-metal (by glTF's Appendix B a pure Lambert surface),
// rendered by Blender 3.4.1 Cycles at 8192-16384 spp (tests/data/cycles/README.md and the JSON
// beside each EXR say how). Our own reference means (scene_render_test.cpp) would follow any error
// of ours; these cannot. Mean luminance must agree within the render's own statistical bound plus
// 1.5 % for the path tracer (the reference's noise is about 1e-4 relMSE; the rest allows for the
// two renderers' pixel sampling and float differences) and 3 % for the photon integrator (whose
// density estimates at final-gather hits are consistent, not unbiased).
#include <cmath>
#include <string>

#include <vector>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "image/exr.h"
#include "image/image.h"
#include "image/metrics.h"
#include "render/path_integrator.h"
#include "photon/photon_integrator.h"
#include "support/estimators.h"
#include "support/small_frame.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"

namespace vkp {
namespace {

const std::string kCycles = std::string(VKPHOTON_TEST_DATA) + "/cycles/";

template <typename Render>
test::Estimate meanLuminanceOverSeeds(int seeds, Render render) {
    std::vector<double> means;
    for (int seed = 0; seed < seeds; ++seed) {
        const RenderResult r = render(uint32_t(900 + seed));
        EXPECT_TRUE(allFinite(r.image));
        means.push_back(meanLuminance(r.image));
    }
    return test::estimate(means);
}

// The file's camera, at the reference's size.
FrameSettings referenceFrame(const ImageRgb& reference, uint32_t spp, uint32_t seed) {
    FrameSettings s = test::smallFrame(reference.width, spp, seed);
    s.height = reference.height;
    return s;
}

// Mean luminance against Cycles' within 5 standard errors plus `tolerance` of the reference.
void expectAgrees(const test::Estimate& e, double reference, double tolerance, const std::string& what) {
    test::expectAgrees(e, reference, 5.0, tolerance, what + " against Cycles");
}

class IndependentReference : public test::GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(IndependentReference, PathTracerMatchesCyclesMeanLuminance) {
    const std::string name = GetParam();
    const ImageRgb reference = readExr(kCycles + name + ".exr");
    const Scene scene = loadGltf(kCycles + name + ".gltf");
    Renderer renderer(test::gpu(), scene);
    const test::Estimate e = meanLuminanceOverSeeds(4, [&](uint32_t seed) {
        return renderer.render<PathIntegrator>(referenceFrame(reference, 16, seed));
    });
    expectAgrees(e, meanLuminance(reference), 0.015, name + ", path tracer");
}

TEST_P(IndependentReference, PhotonIntegratorMatchesCyclesMeanLuminance) {
    const std::string name = GetParam();
    const ImageRgb reference = readExr(kCycles + name + ".exr");
    const Scene scene = loadGltf(kCycles + name + ".gltf");
    Renderer renderer(test::gpu(), scene);
    PhotonIntegratorSettings photons;
    photons.globalPaths = 200000;
    photons.causticPaths = 0;  // nothing specular in these scenes
    const test::Estimate e = meanLuminanceOverSeeds(4, [&](uint32_t seed) {
        return renderer.render<PhotonIntegrator>(referenceFrame(reference, 4, seed), photons);
    });
    expectAgrees(e, meanLuminance(reference), 0.03, name + ", photon integrator");
}

INSTANTIATE_TEST_SUITE_P(Cornell, IndependentReference,
                         ::testing::Values("cornell-box-lambert", "cornell-ceiling-lambert"),
                         [](const auto& info) {
                             std::string n = info.param;
                             for (char& c : n)
                                 if (c == '-') c = '_';
                             return n;
                         });

}  // namespace
}  // namespace vkp
