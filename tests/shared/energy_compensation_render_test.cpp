// White furnace on the GPU: a white sphere under a uniform environment of radiance 1 (nothing else
// in the scene, a convex object: no interreflection) shows, at each pixel, the directional albedo
// of its BSDF towards the camera. With the Kulla-Conty compensation (the default, albedo tables
// read from scene binding kSceneTablesBinding) a rough white metal returns all the light; with
// --no-energy-compensation (Scene::energyCompensation false) it returns the single-scattering
// albedo E(mu, r) of the tables (checked against fresh integration by bsdf_tables_test.cpp).
#include <cmath>

#include <gtest/gtest.h>

#include "gpu_scene/scene_buffers.h"
#include "lights/default_lighting.h"
#include "support/gpu_test_support.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/environment.h"
#include "shared/bsdf.glsl"
#include "shared/gpu_types.glsl"
#include "support/test_scenes.h"
#include "support/small_frame.h"

namespace vkp {
namespace {

constexpr uint32_t kSize = 16;
constexpr double kPiD = 3.14159265358979323846;

Scene whiteSphere(float metallic, float roughness, bool compensation) {
    Scene scene;
    Material m;
    m.baseColor = glm::vec4(1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    scene.materials.push_back(m);
    const int rings = 48, sectors = 96;
    auto point = [&](int r, int s) {
        const double theta = kPiD * r / rings, phi = 2.0 * kPiD * s / sectors;
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        glm::vec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-9f) return;
        n = glm::normalize(n);
        if (glm::dot(n, a + b + c) < 0.0f) std::swap(b, c);
        Triangle t;
        t.p[0] = a;
        t.p[1] = b;
        t.p[2] = c;
        for (int v = 0; v < 3; ++v) {
            t.n[v] = glm::normalize(t.p[v]);  // smooth normals: the sphere's own
            t.uv[v] = glm::vec2(0.0f);
            scene.bounds.grow(t.p[v]);
        }
        scene.triangles.push_back(t);
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < sectors; ++s) {
            add(point(r, s), point(r + 1, s), point(r + 1, s + 1));
            add(point(r, s), point(r + 1, s + 1), point(r, s + 1));
        }
    // 0.2 rad field of view from distance 6: every pixel sees the sphere (cos theta_o 0.6 .. 1).
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f, 0.0f, 6.0f), glm::vec3(0.0f), 0.2f));
    std::string note;
    EnvironmentSettings env;
    env.value = "1";
    applyEnvironment(scene, env, note);
    scene.energyCompensation = compensation;
    return scene;
}

// Mean over the pixels of the rendered image (all channels: white).
double renderMean(const Scene& scene, uint32_t seed) {
    Renderer renderer(test::gpu(), scene);
    FrameSettings s = test::smallFrame(kSize, 64, seed);
    const RenderResult r = renderer.render<PathIntegrator>(s);
    double sum = 0.0;
    for (float v : r.image.pixels) sum += v;
    return sum / double(r.image.pixels.size());
}

// Mean over the pixel centres of E(cos theta_o, roughness): what the plain BRDF must show.
double expectedPlainMetal(const Scene& scene, float roughness) {
    const gpu::GpuCamera cam = makeGpuCamera(scene.cameras[0], kSize, kSize);
    double sum = 0.0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec2 film(x + 0.5f, y + 0.5f);
            const glm::vec3 o = gpu::cameraRayOrigin(cam, kSize, kSize, film);
            const glm::vec3 d = glm::normalize(gpu::cameraRayDirection(cam, kSize, kSize, film));
            const float b = glm::dot(o, d), c = glm::dot(o, o) - 1.0f;
            const float t = -b - std::sqrt(std::max(0.0f, b * b - c));
            const glm::vec3 n = glm::normalize(o + t * d);
            sum += gpu::bsdfTableLookup(gpu::kTableGgxAlbedo, -glm::dot(n, d), roughness);
        }
    return sum / double(kSize * kSize);
}

class EnergyCompensation : public test::GpuTest {};

// Rough white metal (roughness 1: single scattering returns 0.31 .. 0.55 here): compensated 1
// (tolerance 2 %: the tables' interpolation and noise); plain the tables' E (tolerance 2 %).
TEST_F(EnergyCompensation, RoughWhiteMetalFurnace) {
    const double compensated = renderMean(whiteSphere(1.0f, 1.0f, true), 1);
    EXPECT_NEAR(compensated, 1.0, 0.02);
    const Scene plainScene = whiteSphere(1.0f, 1.0f, false);
    const double plain = renderMean(plainScene, 2);
    const double expected = expectedPlainMetal(plainScene, 1.0f);
    EXPECT_LT(expected, 0.6);
    EXPECT_NEAR(plain, expected, 0.02 * expected);
}

// Medium-rough white metal (roughness 0.6, plain albedo ~0.82 at normal incidence).
TEST_F(EnergyCompensation, MediumRoughWhiteMetalFurnace) {
    EXPECT_NEAR(renderMean(whiteSphere(1.0f, 0.6f, true), 3), 1.0, 0.02);
    const Scene plainScene = whiteSphere(1.0f, 0.6f, false);
    EXPECT_NEAR(renderMean(plainScene, 4), expectedPlainMetal(plainScene, 0.6f), 0.02);
}

// Rough white dielectric (ior 1.5, roughness 1): Appendix B's fresnel_mix returns 0.972 .. 0.98 of
// the light for cos theta_o 0.6 .. 1 (tests/shared/bsdf_test.cpp WhiteFurnacePerDirection); the
// compensation adds only the small multiple scattering of the Fresnel-weighted layer (+0.002 ..
// +0.01). Both within 0.015 of 0.98, the compensated one not darker.
TEST_F(EnergyCompensation, RoughWhiteDielectricFurnace) {
    const double compensated = renderMean(whiteSphere(0.0f, 1.0f, true), 5);
    const double plain = renderMean(whiteSphere(0.0f, 1.0f, false), 5);
    EXPECT_NEAR(compensated, 0.98, 0.015);
    EXPECT_NEAR(plain, 0.975, 0.015);
    EXPECT_GE(compensated, plain - 0.002);
}

}  // namespace
}  // namespace vkp
