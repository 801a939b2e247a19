// --light-sampler on the GPU: every sampler estimates the same image. The path tracer's mean
// radiance with the light BVH and the photon cells equals power sampling's (two-sample test over
// seeds) on scenes with 1, 4 and 200 lights (rooms-10x10: 100 quads); the guided path tracer, the
// photon integrator (visible points and final gathers) and SPPM too, on the four-light box.
#include <cmath>

#include <gtest/gtest.h>

#include "support/estimators.h"
#include "support/gpu_test_support.h"
#include "image/image.h"
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

// An open-topped grey box with one single-sided emissive triangle under its missing lid; with
// `more`, a point light, a spot and a sun besides (4 lights, one of them outside the light BVH).
Scene boxScene(bool more) {
    Scene scene = test::shadowTestScene();
    test::addBox(scene, glm::vec3(-2.0f, 0.0f, -2.0f), glm::vec3(2.0f, 3.0f, 2.0f), true);
    // Inward-facing: flip the box's triangles so the camera inside sees their fronts.
    for (Triangle& t : scene.triangles) std::swap(t.p[1], t.p[2]);
    Material emitter;
    emitter.name = "emitter";
    emitter.emissive = glm::vec3(20.0f, 16.0f, 12.0f);
    scene.materials.push_back(emitter);
    Triangle light;
    light.p[0] = glm::vec3(-0.5f, 2.9f, -0.5f);
    light.p[1] = glm::vec3(0.5f, 2.9f, -0.5f);
    light.p[2] = glm::vec3(0.0f, 2.9f, 0.6f);
    light.material = 1;
    for (glm::vec3& n : light.n) n = glm::vec3(0.0f, -1.0f, 0.0f);
    scene.triangles.push_back(light);
    for (const Triangle& t : scene.triangles)
        for (const glm::vec3& p : t.p) scene.bounds.grow(p);
    for (Triangle& t : scene.triangles)
        for (glm::vec3& n : t.n) n = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    if (more) {
        test::addPointLight(scene, glm::vec3(1.0f, 1.5f, 1.0f), glm::vec3(3.0f));
        test::addSunAndSpot(scene, glm::vec3(1.0f), glm::vec3(20.0f));
    }
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f, 1.5f, 1.8f), glm::vec3(0.0f, 0.8f, -2.0f)));
    return scene;
}

enum class IntegratorKind { Path, Guided, Photon, ProgressivePhoton };

test::Estimate meanOverSeeds(const Scene& scene, LightSampling sampling, uint32_t size, uint32_t spp, int seeds,
                      uint32_t maxDepth = 3, IntegratorKind kind = IntegratorKind::Path) {
    Renderer renderer(test::gpu(), scene, sampling);
    std::vector<double> means;
    for (int seed = 0; seed < seeds; ++seed) {
        FrameSettings s = test::smallFrame(size, spp, 300 + seed);
        s.maxDepth = maxDepth;
        GuideSettings guide;
        guide.photons = 10000;
        PhotonIntegratorSettings photon;  // the same photon maps for every sampler (same seed)
        photon.globalPaths = 10000;
        photon.causticPaths = 2000;
        photon.gatherRays = 1;
        const RenderResult r = kind == IntegratorKind::Path     ? renderer.render<PathIntegrator>(s)
                               : kind == IntegratorKind::Guided ? renderer.render<GuidedIntegrator>(s, guide)
                               : kind == IntegratorKind::Photon ? renderer.render<PhotonIntegrator>(s, photon)
                                                                : renderer.render<ProgressivePhotonIntegrator>(s, photon);
        EXPECT_EQ(r.stats.get<uint64_t>("counters.nonFiniteSamples"), 0u);
        means.push_back(meanValue(r.image));
    }
    return test::estimate(means);
}

void expectSameMean(const Scene& scene, const std::string& name, uint32_t size, uint32_t spp,
                    LightSampling a = {LightSampler::Power}, LightSampling b = {LightSampler::Bvh},
                    uint32_t maxDepth = 3, IntegratorKind kind = IntegratorKind::Path) {
    constexpr int kSeeds = 6;
    const test::Estimate power = meanOverSeeds(scene, a, size, spp, kSeeds, maxDepth, kind);
    const test::Estimate bvh = meanOverSeeds(scene, b, size, spp, kSeeds, maxDepth, kind);
    ASSERT_GT(power.mean, 0.0);
    // 5 standard errors of the difference (t, 10 dof: ~0.05% two-sided) plus 0.5% for float noise.
    test::expectAgree(bvh, power, 5.0, 0.005, name);
}

class LightSamplerRender : public test::GpuTest {};

// Solid-angle sampling of the emissive triangles estimates the same direct light as the area
// sampling it replaced (depth 1: direct light only, where the two differ most), and the same image.
TEST_F(LightSamplerRender, SolidAngleMeanEqualsAreaSamplingOnTheCornellBox) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-box.gltf");
    const LightSampling area{LightSampler::Power, TriangleSampling::Area};
    const LightSampling solidAngle{LightSampler::Power, TriangleSampling::SolidAngle};
    expectSameMean(scene, "cornell-box direct", 32, 16, area, solidAngle, 1);
    expectSameMean(scene, "cornell-box", 32, 16, area, solidAngle, 3);
}

TEST_F(LightSamplerRender, BvhMeanEqualsPowerWithOneLight) {
    const Scene scene = boxScene(false);
    ASSERT_EQ(buildSceneArrays(scene).lights.size(), 1u);
    expectSameMean(scene, "one light", 32, 16);
}

TEST_F(LightSamplerRender, BvhMeanEqualsPowerWithFourLights) {
    const Scene scene = boxScene(true);
    ASSERT_EQ(buildSceneArrays(scene).lights.size(), 4u);
    expectSameMean(scene, "four lights", 32, 16);
}

// The photon cells' mixture (cells where photons arrived, the BVH floor elsewhere) with one emissive
// triangle, and with four lights of every kind (triangle, point, spot, sun: the sun stays outside the
// tree and the cells), estimates the same image as power sampling.
TEST_F(LightSamplerRender, PhotonCellsMeanEqualsPowerWithOneAndFourLights) {
    LightSampling photon{LightSampler::Photon};
    photon.cellPhotons = 20000;
    for (const bool more : {false, true}) {
        const Scene scene = boxScene(more);
        ASSERT_EQ(buildSceneArrays(scene).lights.size(), more ? 4u : 1u);
        expectSameMean(scene, more ? "four lights, photon" : "one light, photon", 32, 16, {LightSampler::Power},
                       photon);
    }
}

TEST_F(LightSamplerRender, BvhMeanEqualsPowerInTheHundredRooms) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/rooms-10x10.gltf");
    ASSERT_EQ(buildSceneArrays(scene).lights.size(), 200u);  // 100 quads
    expectSameMean(scene, "rooms-10x10", 32, 16);
}

// Photon light cells (Keller & Wald section 3 with a floor) estimate the same image as power sampling
// in the hundred rooms and behind the slit (door-slit: the camera's room is lit only through it).
TEST_F(LightSamplerRender, PhotonCellsMeanEqualsPower) {
    LightSampling photon{LightSampler::Photon};
    photon.cellPhotons = 50000;
    for (const char* name : {"rooms-10x10", "door-slit"}) {
        const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/" + name + ".gltf");
        expectSameMean(scene, name, 32, 16, {LightSampler::Power}, photon);
    }
}

// Every integrator that estimates direct light with next-event estimation: bvh and photon cells
// against power on the box with four lights (one directional, outside the light BVH). The photon
// integrators' photon maps are the same for every sampler (same seeds), so their density
// estimation bias cancels and only next-event estimation differs.
class LightSamplerEveryIntegrator : public test::GpuTest, public ::testing::WithParamInterface<IntegratorKind> {};

TEST_P(LightSamplerEveryIntegrator, BvhAndPhotonCellsMeanEqualsPower) {
    const Scene scene = boxScene(true);
    LightSampling photon{LightSampler::Photon};
    photon.cellPhotons = 20000;
    expectSameMean(scene, "four lights, bvh", 24, 8, {LightSampler::Power}, {LightSampler::Bvh}, 3, GetParam());
    expectSameMean(scene, "four lights, photon cells", 24, 8, {LightSampler::Power}, photon, 3, GetParam());
}

std::string integratorName(const ::testing::TestParamInfo<IntegratorKind>& info) {
    constexpr const char* kNames[] = {"path", "guided", "photon", "progressive_photon"};
    return kNames[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(NextEventEstimators, LightSamplerEveryIntegrator,
                         ::testing::Values(IntegratorKind::Guided, IntegratorKind::Photon,
                                           IntegratorKind::ProgressivePhoton),
                         integratorName);

// Same seed, same sampler: the same image bit for bit.
TEST_F(LightSamplerRender, BvhIsReproducible) {
    const Scene scene = boxScene(true);
    Renderer renderer(test::gpu(), scene, {LightSampler::Bvh});
    FrameSettings s = test::smallFrame(16, 4);
    const RenderResult a = renderer.render<PathIntegrator>(s);
    const RenderResult b = renderer.render<PathIntegrator>(s);
    EXPECT_EQ(a.image.pixels, b.image.pixels);
    EXPECT_EQ(a.stats.get<std::string>("light_sampler.mode"), "bvh");
}

}  // namespace
}  // namespace vkp
