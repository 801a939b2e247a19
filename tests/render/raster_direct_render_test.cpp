// --direct raster against --direct traced (next-event estimation, the reference). Point lights:
// the raster term equals the expectation of the traced estimate at the same pixel centres, so the
// raster image may differ from a traced one only by the traced image's own noise: its relative MSE
// to a traced render must be about half that between two independent traced renders (which holds
// twice the noise), and a bias would add to it. Area lights (point samples) converge towards the
// traced result as --area-light-samples grows. Full renders (all bounces) agree in mean radiance.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "image/metrics.h"
#include "guiding/guided_integrator.h"
#include "render/path_integrator.h"
#include "photon/photon_integrator.h"
#include "photon/progressive_photon_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/test_scenes.h"
#include "support/small_frame.h"

namespace vkp {
namespace {

Scene pointLitScene() {
    Scene scene = test::shadowTestScene();
    test::addQuad(scene, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4});
    test::addBox(scene, {-0.5f, 0.5f, -0.5f}, {0.5f, 1.5f, 0.5f});
    test::addBox(scene, {0.8f, 0.0f, 0.6f}, {1.4f, 0.4f, 1.2f}, true);  // open: per-triangle volumes
    test::addPointLight(scene, {0.3f, 3.0f, 0.2f}, {6.0f, 5.0f, 4.0f});
    test::addPointLight(scene, {-2.0f, 2.5f, 1.0f}, {2.0f, 3.0f, 6.0f});
    test::addPointLight(scene, {1.5f, 2.0f, -1.5f}, glm::vec3(4.0f));
    test::addPointLight(scene, {2.5f, 1.0f, 2.5f}, glm::vec3(3.0f));
    test::addPointLight(scene, {-1.0f, 1.8f, -2.0f}, glm::vec3(2.0f));  // a second mask pass
    scene.cameras.push_back(test::lookAt({0.5f, 3.0f, 4.5f}, {0.2f, 0.3f, 0.3f}));
    return scene;
}

FrameSettings directOnly(DirectLight direct, uint32_t spp, uint32_t seed) {
    FrameSettings s = test::smallFrame(64, spp, seed);
    s.maxDepth = 1;          // emission + direct light at the first vertex
    s.pixelCentres = true;   // where the raster pass evaluates
    s.direct = direct;
    return s;
}

class RasterDirect : public test::GpuTest {};

// Direct light only: the raster image against a 64-spp traced one, compared with the noise of two
// traced images. Returns the raster image.
ImageRgb expectRasterMatchesTraced(Renderer& renderer, const char* what) {
    const ImageRgb raster = renderer.render<PathIntegrator>(directOnly(DirectLight::Raster, 1, 1)).image;
    const ImageRgb traced1 = renderer.render<PathIntegrator>(directOnly(DirectLight::Traced, 64, 1)).image;
    const ImageRgb traced2 = renderer.render<PathIntegrator>(directOnly(DirectLight::Traced, 64, 2)).image;
    const double rasterError = relativeMse(raster, traced1);
    const double noise = relativeMse(traced2, traced1);
    fmt::print("{}: relMSE(raster, traced) = {:.3g}, relMSE(traced, traced') = {:.3g}\n", what, rasterError, noise);
    EXPECT_GT(meanLuminance(raster), 0.01) << what;
    // Unbiased: E[raster error] = noise / 2. Allow 30 % over it for the noise of the estimate.
    EXPECT_LT(rasterError, 0.65 * noise) << what;
    return raster;
}

TEST_F(RasterDirect, PointLightsMatchTracedUpToSamplingNoise) {
    const Scene scene = pointLitScene();
    Renderer renderer(test::gpu(), scene);
    const ImageRgb raster = expectRasterMatchesTraced(renderer, "point lights");
    // And the raster image is noise-free: rendering it again gives the same bits.
    const ImageRgb again = renderer.render<PathIntegrator>(directOnly(DirectLight::Raster, 1, 7)).image;
    EXPECT_EQ(again.pixels, raster.pixels);
}

TEST_F(RasterDirect, SpotAndDirectionalLightsMatchTracedUpToSamplingNoise) {
    Scene scene = pointLitScene();
    scene.lights.resize(1);
    test::addSunAndSpot(scene, glm::vec3(0.5f, 0.4f, 0.3f), glm::vec3(8.0f));
    Renderer renderer(test::gpu(), scene);
    expectRasterMatchesTraced(renderer, "spot + directional");
}

TEST_F(RasterDirect, AreaLightSamplesConvergeToTraced) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-box.gltf");
    Renderer renderer(test::gpu(), scene);
    const ImageRgb reference = renderer.render<PathIntegrator>(directOnly(DirectLight::Traced, 256, 3)).image;
    double previous = 1e30;
    for (uint32_t samples : {1u, 8u, 64u}) {
        FrameSettings s = directOnly(DirectLight::Raster, 1, 1);
        s.areaLightSamples = samples;
        const double error = relativeMse(renderer.render<PathIntegrator>(s).image, reference);
        fmt::print("area light, {} samples per triangle: relMSE to traced = {:.4g}\n", samples, error);
        EXPECT_LT(error, previous) << samples << " samples per emissive triangle";
        previous = error;
    }
    EXPECT_LT(previous, 0.02);
}

// The "same picture" check: cornell-box, all bounces (the indirect light's noise dominates
// both), --direct raster against --direct traced. Without bias, E[relMSE(raster, traced)] is the
// sum of the two images' noise, each estimated as half the relMSE between two renders with other
// seeds; the measured distance may exceed it by 30 %, no more: the estimates' own scatter (~10 %
// for these heavy-tailed images) plus the raster pass's one designed bias, 256 point lights per
// emissive triangle for an area light (AreaLightSamplesConvergeToTraced measures it), which
// shows since the camera paths' Owen-Sobol samples halved the traced noise (it measured 1.16x).
TEST_F(RasterDirect, CornellBoxSamePictureAsTraced) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-box.gltf");
    Renderer renderer(test::gpu(), scene);
    auto settings = [](DirectLight direct, uint32_t seed) {
        FrameSettings s = test::smallFrame(64, 64, seed);
        s.pixelCentres = true;
        s.areaLightSamples = 256;
        s.direct = direct;
        return s;
    };
    const ImageRgb raster = renderer.render<PathIntegrator>(settings(DirectLight::Raster, 1)).image;
    const ImageRgb traced1 = renderer.render<PathIntegrator>(settings(DirectLight::Traced, 2)).image;
    const ImageRgb traced2 = renderer.render<PathIntegrator>(settings(DirectLight::Traced, 3)).image;
    const double rasterError = relativeMse(raster, traced1);
    const double noise = relativeMse(traced2, traced1);
    const ImageRgb raster2 = renderer.render<PathIntegrator>(settings(DirectLight::Raster, 4)).image;
    const double rasterNoise = relativeMse(raster2, raster);
    fmt::print("cornell-box: relMSE(raster, traced) = {:.4g}, relMSE(traced, traced') = {:.4g}, relMSE(raster, raster') = {:.4g}\n",
               rasterError, noise, rasterNoise);
    EXPECT_LT(rasterError, 1.3 * (0.5 * noise + 0.5 * rasterNoise));
}

// All bounces: the raster direct term plus the path tracer's remaining terms estimate the same
// image as the traced reference, for point lights and for the Cornell box's area light.
// Every integrator that takes --direct raster (path, guided, photon two-pass and progressive):
// the same mean with the raster direct light as with next-event estimation.
enum class FullRenderKind { Path, Guided, Photon, ProgressivePhoton };

class RasterDirectFullRender : public test::GpuTest, public ::testing::WithParamInterface<FullRenderKind> {};

TEST_P(RasterDirectFullRender, MeansAgree) {
    const FullRenderKind kind = GetParam();
    for (int sceneIndex = 0; sceneIndex < 2; ++sceneIndex) {
        const Scene scene = sceneIndex == 0 ? pointLitScene()
                                            : loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-box.gltf");
        Renderer renderer(test::gpu(), scene);
        constexpr int kSeeds = 4;
        std::array<double, 2> sum{0, 0}, sumSq{0, 0};
        for (int mode = 0; mode < 2; ++mode)
            for (int seed = 0; seed < kSeeds; ++seed) {
                FrameSettings s = test::smallFrame(32, kind == FullRenderKind::ProgressivePhoton ? 8 : 16, 300 + seed);
                s.maxDepth = 4;
                s.pixelCentres = true;
                s.areaLightSamples = 64;
                s.direct = mode == 0 ? DirectLight::Raster : DirectLight::Traced;
                GuideSettings guide;
                guide.photons = 10000;
                PhotonIntegratorSettings photon;
                photon.globalPaths = 10000;
                photon.causticPaths = 0;
                photon.gatherRays = 1;
                const RenderResult r =
                    kind == FullRenderKind::Path     ? renderer.render<PathIntegrator>(s)
                    : kind == FullRenderKind::Guided ? renderer.render<GuidedIntegrator>(s, guide)
                    : kind == FullRenderKind::Photon ? renderer.render<PhotonIntegrator>(s, photon)
                                                     : renderer.render<ProgressivePhotonIntegrator>(s, photon);
                const double m = meanLuminance(r.image);
                sum[mode] += m;
                sumSq[mode] += m * m;
            }
        double se2 = 0.0;
        std::array<double, 2> mean{};
        for (int mode = 0; mode < 2; ++mode) {
            mean[mode] = sum[mode] / kSeeds;
            se2 += std::max(0.0, (sumSq[mode] - kSeeds * mean[mode] * mean[mode]) / (kSeeds - 1)) / kSeeds;
        }
        fmt::print("scene {}: mean raster {:.5g}, traced {:.5g}, standard error {:.3g}\n", sceneIndex, mean[0], mean[1],
                   std::sqrt(se2));
        // 5 standard errors plus 1 % for the area light's point-sample approximation.
        EXPECT_NEAR(mean[0], mean[1], 5.0 * std::sqrt(se2) + 0.01 * mean[1]) << "scene " << sceneIndex;
    }
}

std::string fullRenderName(const ::testing::TestParamInfo<FullRenderKind>& info) {
    constexpr const char* kNames[] = {"path", "guided", "photon", "progressive_photon"};
    return kNames[static_cast<int>(info.param)];
}

// One test per integrator, so that ctest runs them side by side.
INSTANTIATE_TEST_SUITE_P(EveryIntegrator, RasterDirectFullRender,
                         ::testing::Values(FullRenderKind::Path, FullRenderKind::Guided, FullRenderKind::Photon,
                                           FullRenderKind::ProgressivePhoton),
                         fullRenderName);

}  // namespace
}  // namespace vkp

namespace vkp {
namespace {

// The raster/compute hand-off (volume build -> vertex input, stencil -> mask -> copy -> lighting
// -> path tracer) under the validation layer's synchronization validation, on a context of its
// own: any hazard message fails the test.
TEST(RasterDirectSync, NoHazardsUnderSynchronizationValidation) {
    vk::ContextOptions options;
    options.validate = true;
    options.synchronizationValidation = true;
    vk::Context context(options);
    Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-box.gltf");
    for (int i = 0; i < 5; ++i)  // two mask passes of point lights besides the area samples
        test::addPointLight(scene, scene.bounds.min + glm::vec3(0.2f + 0.15f * i, 0.6f, 0.5f) * scene.bounds.extent(),
                            glm::vec3(0.5f));
    Renderer renderer(context, scene);
    FrameSettings s = test::smallFrame(24, 2);
    s.direct = DirectLight::Raster;
    s.areaLightSamples = 3;
    const RenderResult r = renderer.render<PathIntegrator>(s);
    EXPECT_GT(meanLuminance(r.image), 0.0);
    const auto messages = context.validationMessages();
    EXPECT_EQ(context.validationMessageCount(), 0u) << (messages.empty() ? "" : messages.front());
}

}  // namespace
}  // namespace vkp

namespace vkp {
namespace {

// The skip rule the path tracer and the visible points share (shared/gpu_types.glsl): only the
// first vertex skips covered lights, and only emission reached from it by a non-delta bounce is
// dropped.
TEST(RasterSkipRule, OnlyTheFirstVertexSkipsCoveredLights) {
    using namespace gpu;
    const uint32_t delta = (1u << kLightPoint) | (1u << kLightSpot) | (1u << kLightDirectional);
    const uint32_t area = 1u << kLightTriangle;
    EXPECT_FALSE(rasterDirectLightOn(0u));
    EXPECT_FALSE(rasterDirectLightOn(kPathFlagPixelCentres));
    EXPECT_TRUE(rasterDirectLightOn(kPathFlagRasterDeltaLights));
    EXPECT_TRUE(rasterDirectLightOn(kPathFlagRasterAreaLights));
    EXPECT_EQ(rasterCoveredLightTypes(0u, 0u), 0u);
    EXPECT_EQ(rasterCoveredLightTypes(kPathFlagRasterDeltaLights, 0u), delta);
    EXPECT_EQ(rasterCoveredLightTypes(kPathFlagRasterAreaLights, 0u), area);
    EXPECT_EQ(rasterCoveredLightTypes(kPathFlagRasterDeltaLights | kPathFlagRasterAreaLights, 0u), delta | area);
    EXPECT_EQ(rasterCoveredLightTypes(kPathFlagRasterDeltaLights | kPathFlagRasterAreaLights, 1u), 0u);
    EXPECT_TRUE(rasterCoversEmission(kPathFlagRasterAreaLights, 1u, false));
    EXPECT_FALSE(rasterCoversEmission(kPathFlagRasterAreaLights, 1u, true));   // behind a mirror
    EXPECT_FALSE(rasterCoversEmission(kPathFlagRasterAreaLights, 0u, true));   // seen by the camera
    EXPECT_FALSE(rasterCoversEmission(kPathFlagRasterAreaLights, 2u, false));
    EXPECT_FALSE(rasterCoversEmission(kPathFlagRasterDeltaLights, 1u, false));
}

}  // namespace
}  // namespace vkp
