// Photon tracing on the GPU: energy balance against closed-form answers, caustic classification,
// and reproducibility.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "gpu_scene/scene_buffers.h"
#include "photon/photon_tracer.h"
#include "scene/gltf_loader.h"
#include "shared/photon.glsl"
#include "shared/sampling.glsl"
#include "support/test_scenes.h"

namespace vkp {
namespace {

struct TracedPhotons {
    PhotonCounters counters;
    std::vector<gpu::GpuPhoton> photons;
    double nominalPower = 0.0;
};

TracedPhotons tracePhotons(const Scene& scene, const PhotonSettings& settings) {
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(test::gpu(), arrays);
    PhotonTracer tracer(test::gpu(), scene, arrays, buffers);
    TracedPhotons result;
    result.counters = tracer.trace(settings);
    result.photons = tracer.downloadPhotons();
    result.nominalPower = tracer.nominalPhotonPower();
    return result;
}

class PhotonTrace : public test::GpuTest {};

// In the furnace (a closed Lambertian cube of albedo a whose faces all emit from both sides), half
// the emitted power leaves through the outer faces and the inner half is stored at every bounce:
// the expected stored power per emitted photon is 0.5 * (1 + a + a^2 + ...) = 0.5 / (1 - a).
TEST_F(PhotonTrace, FurnaceEnergyBalance) {
    const float albedo = 0.5f;
    PhotonSettings settings;
    settings.paths = 100000;
    settings.maxDeposits = 24;  // a path storing more has probability 0.5^23
    const TracedPhotons traced = tracePhotons(test::furnaceScene(albedo, 1.0f), settings);
    double stored = 0.0, storedSq = 0.0;
    std::vector<double> perPath(settings.paths, 0.0);
    for (size_t i = 0; i < traced.photons.size(); ++i) {
        const gpu::GpuPhoton& p = traced.photons[i];
        if (!(gpu::photonFlags(p) & gpu::kPhotonValid)) continue;
        perPath[i / settings.maxDeposits] += gpu::photonRelativePower(p).x;
    }
    for (double v : perPath) { stored += v; storedSq += v * v; }
    const double mean = stored / settings.paths;
    const double standardError = std::sqrt((storedSq / settings.paths - mean * mean) / settings.paths);
    EXPECT_NEAR(mean, 0.5 / (1.0 - albedo), 5.0 * standardError + 1e-3) << "standard error " << standardError;
    // Half the paths leave the cube at once; none of the others can escape.
    EXPECT_NEAR(double(traced.counters.lost) / settings.paths, 0.5, 0.01);
    EXPECT_EQ(traced.counters.truncated, 0u);
    EXPECT_EQ(traced.counters.storedCaustic, 0u);  // no specular surfaces
    EXPECT_EQ(traced.counters.lost + traced.counters.absorbed + traced.counters.truncated, settings.paths);
    // Nominal power: every face emits pi * Le * area from each side.
    EXPECT_NEAR(traced.nominalPower * settings.paths, gpu::kPi * 1.0 * 4.0 * 6.0 * 2.0, 1e-3);
}

// A path with more deposits than slots keeps a uniform sample of them, weighted up (reservoir
// sampling): in a furnace of albedo 0.8 with 4 slots per path (a quarter of the paths make more
// deposits) the stored power per path is still 0.5 / (1 - a) = 2.5 (cutting the paths at their
// slots stored 0.5 (1 - a^4) / (1 - a) = 1.48), the kinds' counters count the photons in the
// slots, and the same seed gives the same slots.
TEST_F(PhotonTrace, FurnaceEnergyBalanceWithFewerSlotsThanDeposits) {
    const float albedo = 0.8f;
    PhotonSettings settings;
    settings.paths = 100000;
    settings.maxDeposits = 4;
    const Scene furnace = test::furnaceScene(albedo, 1.0f);
    const TracedPhotons traced = tracePhotons(furnace, settings);
    double stored = 0.0, storedSq = 0.0;
    uint64_t valid = 0, primary = 0;
    std::vector<double> perPath(settings.paths, 0.0);
    for (size_t i = 0; i < traced.photons.size(); ++i) {
        const gpu::GpuPhoton& p = traced.photons[i];
        if (!(gpu::photonFlags(p) & gpu::kPhotonValid)) continue;
        valid += 1;
        primary += (gpu::photonFlags(p) & gpu::kPhotonPrimary) ? 1 : 0;
        perPath[i / settings.maxDeposits] += gpu::photonRelativePower(p).x;
    }
    for (double v : perPath) { stored += v; storedSq += v * v; }
    const double mean = stored / settings.paths;
    const double standardError = std::sqrt((storedSq / settings.paths - mean * mean) / settings.paths);
    EXPECT_NEAR(mean, 0.5 / (1.0 - albedo), 5.0 * standardError + 2e-3) << "standard error " << standardError;
    // The inner half of the paths make 1 + Geometric deposits: more than 4 with probability a^4.
    EXPECT_NEAR(double(traced.counters.sampled) / settings.paths, 0.5 * std::pow(albedo, 4.0f), 0.01);
    EXPECT_EQ(traced.counters.storedGlobal + traced.counters.storedPrimary, valid);
    EXPECT_EQ(traced.counters.storedPrimary, primary);
    EXPECT_LT(traced.counters.truncated, settings.paths / 10000);  // only paths past kPhotonMaxBounces
    const TracedPhotons again = tracePhotons(furnace, settings);
    EXPECT_EQ(std::memcmp(again.photons.data(), traced.photons.data(), traced.photons.size() * sizeof(gpu::GpuPhoton)), 0);
}

// The first hits of the photons emitted by a one-sided ceiling light in a closed box carry the
// light's whole power: each primary photon has relative luminance 1 and none is lost.
TEST_F(PhotonTrace, PrimaryPhotonsCarryTheLightPower) {
    Scene scene = test::furnaceScene(0.5f, 0.0f);
    Material light;
    light.name = "light";
    light.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    light.emissive = glm::vec3(5.0f, 3.0f, 1.0f);
    scene.materials.push_back(light);
    Triangle a, b;
    const glm::vec3 q[4] = {{-0.3f, 0.99f, -0.3f}, {0.3f, 0.99f, -0.3f}, {0.3f, 0.99f, 0.3f}, {-0.3f, 0.99f, 0.3f}};
    a.p[0] = q[0]; a.p[1] = q[1]; a.p[2] = q[2];  // counter-clockwise seen from below: faces -y
    b.p[0] = q[0]; b.p[1] = q[2]; b.p[2] = q[3];
    for (Triangle* t : {&a, &b}) {
        for (auto& n : t->n) n = glm::vec3(0, -1, 0);
        for (auto& uv : t->uv) uv = glm::vec2(0.0f);
        t->material = 1;
        scene.triangles.push_back(*t);
    }
    PhotonSettings settings;
    settings.paths = 50000;
    settings.maxDeposits = 24;  // every deposit in its slot (else a primary photon may be sampled out and the rest weighted up)
    const TracedPhotons traced = tracePhotons(scene, settings);
    EXPECT_EQ(traced.counters.sampled, 0u);
    uint64_t primary = 0;
    glm::dvec3 sum(0.0);
    for (const auto& p : traced.photons) {
        if (!(gpu::photonFlags(p) & gpu::kPhotonPrimary)) continue;
        ++primary;
        const glm::vec3 power = gpu::photonRelativePower(p);
        sum += glm::dvec3(power);
        EXPECT_NEAR(gpu::luminance(power), 1.0f, 2e-3f);
        EXPECT_LT(p.position.y, 0.99f);  // all first hits are below the light
    }
    EXPECT_EQ(primary, settings.paths);
    EXPECT_EQ(traced.counters.storedPrimary, settings.paths);
    // Per channel the light's colour, normalised to luminance 1.
    const double lum = gpu::luminance(glm::vec3(5.0f, 3.0f, 1.0f));
    EXPECT_NEAR(sum.x / settings.paths, 5.0 / lum, 1e-2);
    EXPECT_NEAR(sum.z / settings.paths, 1.0 / lum, 1e-2);
}

TEST_F(PhotonTrace, ReproducibleWithTheSameSeed) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-glass.gltf");
    PhotonSettings settings;
    settings.paths = 20000;
    settings.seed = 5;
    const TracedPhotons a = tracePhotons(scene, settings);
    const TracedPhotons b = tracePhotons(scene, settings);
    ASSERT_EQ(a.photons.size(), b.photons.size());
    EXPECT_EQ(std::memcmp(a.photons.data(), b.photons.data(), a.photons.size() * sizeof(gpu::GpuPhoton)), 0);
    settings.seed = 6;
    const TracedPhotons c = tracePhotons(scene, settings);
    EXPECT_NE(std::memcmp(a.photons.data(), c.photons.data(), a.photons.size() * sizeof(gpu::GpuPhoton)), 0);
}

// The glass sphere of cornell-glass focuses light on the floor below it: caustic photons
// (light -> specular -> diffuse) concentrate there, and only there do they outnumber the floor's
// global photons per area by far.
TEST_F(PhotonTrace, GlassSphereCausticLandsUnderTheSphere) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-glass.gltf");
    PhotonSettings settings;
    settings.paths = 100000;
    const TracedPhotons traced = tracePhotons(scene, settings);
    const glm::vec2 sphereFoot(0.35f, 0.25f);  // scripts/make_scenes.py: glass sphere centre (x, z)
    uint64_t caustic = 0, causticNearSphere = 0, primaryFlaggedCaustic = 0;
    for (const auto& p : traced.photons) {
        const uint32_t flags = gpu::photonFlags(p);
        if (!(flags & gpu::kPhotonCaustic)) continue;
        ++caustic;
        primaryFlaggedCaustic += (flags & gpu::kPhotonPrimary) != 0;
        const bool onFloor = p.position.y < 1e-3f;
        if (onFloor && glm::distance(glm::vec2(p.position.x, p.position.z), sphereFoot) < 0.35f) ++causticNearSphere;
    }
    EXPECT_EQ(caustic, traced.counters.storedCaustic);
    EXPECT_EQ(primaryFlaggedCaustic, 0u);
    EXPECT_GT(caustic, settings.paths / 100);
    // The disk under the sphere is ~1/10 of the floor but holds a large share of the caustic.
    EXPECT_GT(double(causticNearSphere) / caustic, 0.25) << causticNearSphere << " of " << caustic;
}

}  // namespace
}  // namespace vkp
