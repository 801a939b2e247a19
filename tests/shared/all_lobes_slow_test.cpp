// The path tracer and the photon integrators on one scene using every lobe of the BSDF:
// the Cornell box (diffuse walls) with its tall box a rough gold metal, its short box a blue
// diffuse under a rough clear coat, a sheen sphere, a dielectric with a tinted specular
// (KHR_materials_specular) on the short box and a rough solid glass sphere (transmission 1,
// roughness 0.3). The photon estimates blur glossy lobes over the gather radius and the
// photon integrators see lights through rough glass by caustic photons, not by BSDF sampling;
// their expected image differs from the path tracer's only by the density-estimation bias, which
// the mean over the image and over large blocks keeps small. The glass sphere floats, so that the
// caustic it focuses on the floor is in view; a 5x5 window there is compared as well.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "gpu_scene/scene_buffers.h"
#include "support/gpu_test_support.h"
#include "image/metrics.h"
#include "render/path_integrator.h"
#include "photon/photon_integrator.h"
#include "photon/progressive_photon_integrator.h"
#include "render/renderer.h"
#include "support/test_scenes.h"
#include "support/small_frame.h"

namespace vkp {
namespace {

constexpr uint32_t kSize = 32;
const glm::vec3 kGlassCentre(-0.5f, 0.55f, 0.5f);
const glm::vec3 kLightCentre(0.0f, 1.98f, 0.0f);  // scripts/make_scenes.py cornell_room

void addSphere(Scene& scene, glm::vec3 centre, float radius, uint32_t material) {
    const int rings = 16, sectors = 32;
    const auto point = [&](int r, int s) {
        const float theta = 3.14159265f * r / rings, phi = 6.2831853f * s / sectors;
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    const auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        glm::vec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-9f) return;
        if (glm::dot(n, a + b + c) < 0.0f) std::swap(b, c);
        Triangle t;
        const glm::vec3 unit[3] = {a, b, c};
        for (int v = 0; v < 3; ++v) {
            t.p[v] = centre + radius * unit[v];
            t.n[v] = glm::normalize(unit[v]);
            t.uv[v] = glm::vec2(0.0f);
            scene.bounds.grow(t.p[v]);
        }
        t.material = material;
        scene.triangles.push_back(t);
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < sectors; ++s) {
            add(point(r, s), point(r + 1, s), point(r + 1, s + 1));
            add(point(r, s), point(r + 1, s + 1), point(r, s + 1));
        }
}

uint32_t addMaterial(Scene& scene, Material m) {
    scene.materials.push_back(m);
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

Scene allLobesScene() {
    Scene scene = test::shippedScene("cornell-box");
    Material metal;
    metal.name = "rough gold";
    metal.baseColor = glm::vec4(0.9f, 0.7f, 0.35f, 1.0f);
    metal.metallic = 1.0f;
    metal.roughness = 0.4f;
    const uint32_t metalIndex = addMaterial(scene, metal);
    Material coated;
    coated.name = "blue under a rough coat";
    coated.baseColor = glm::vec4(0.15f, 0.25f, 0.7f, 1.0f);
    coated.metallic = 0.0f;
    coated.roughness = 0.8f;
    coated.clearcoat = 1.0f;
    coated.clearcoatRoughness = 0.25f;
    const uint32_t coatedIndex = addMaterial(scene, coated);
    // The boxes: the white triangles above the floor that are not walls (|x|, |z| < 0.95, y < 1.9).
    for (Triangle& t : scene.triangles) {
        if (scene.materials[t.material].name != "white") continue;
        const glm::vec3 c = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        if (std::abs(c.x) > 0.95f || std::abs(c.z) > 0.95f || c.y < 0.01f || c.y > 1.9f) continue;
        t.material = c.x < 0.0f ? metalIndex : coatedIndex;  // tall box left, short box right
    }
    Material sheen;
    sheen.name = "sheen";
    sheen.baseColor = glm::vec4(0.35f, 0.08f, 0.1f, 1.0f);
    sheen.metallic = 0.0f;
    sheen.roughness = 0.9f;
    sheen.sheenColor = glm::vec3(0.9f, 0.9f, 0.8f);
    sheen.sheenRoughness = 0.5f;
    addSphere(scene, {-0.05f, 0.18f, 0.8f}, 0.18f, addMaterial(scene, sheen));
    Material tinted;
    tinted.name = "tinted specular";
    tinted.baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    tinted.metallic = 0.0f;
    tinted.roughness = 0.3f;
    tinted.specularColor = glm::vec3(1.0f, 0.4f, 0.2f);
    addSphere(scene, {0.35f, 0.85f, 0.3f}, 0.25f, addMaterial(scene, tinted));
    Material glass;
    glass.name = "rough glass";
    glass.baseColor = glm::vec4(0.95f, 0.95f, 1.0f, 1.0f);
    glass.metallic = 0.0f;
    glass.roughness = 0.3f;
    glass.transmission = 1.0f;
    glass.thickness = 0.4f;  // KHR_materials_volume: a solid that refracts
    addSphere(scene, kGlassCentre, 0.2f, addMaterial(scene, glass));  // floating: its caustic is in view
    return scene;
}

FrameSettings frame(uint32_t spp, uint32_t seed) {
    FrameSettings s = test::smallFrame(kSize, spp, seed);
    return s;
}

// The pixel where the rough glass sphere focuses the light's centre on the floor (the caustic).
glm::vec2 causticPixel(const Scene& scene) {
    const glm::vec3 focus = kLightCentre + (kGlassCentre - kLightCentre) * (kLightCentre.y / (kLightCentre.y - kGlassCentre.y));
    const gpu::GpuCamera cam = makeGpuCamera(chooseCamera(scene, -1), kSize, kSize);
    const glm::vec3 d = focus - cam.position;
    const float z = glm::dot(d, cam.forward);
    const float ndcX = glm::dot(d, cam.right) / (z * cam.aspect * cam.tanHalfFovY);
    const float ndcY = glm::dot(d, cam.up) / (z * cam.tanHalfFovY);
    return {0.5f * (ndcX + 1.0f) * kSize, 0.5f * (1.0f - ndcY) * kSize};
}

// Mean luminance of the 5 x 5 pixels around `centre`, moved inside the image.
double windowLuminance(const ImageRgb& image, glm::vec2 centre) {
    const int cx = std::clamp(int(centre.x), 2, int(image.width) - 3), cy = std::clamp(int(centre.y), 2, int(image.height) - 3);
    double sum = 0.0;
    for (int y = cy - 2; y <= cy + 2; ++y)
        for (int x = cx - 2; x <= cx + 2; ++x) {
            const float* p = &image.pixels[3 * (size_t(y) * image.width + x)];
            sum += luminance(p[0], p[1], p[2]);
        }
    return sum / 25.0;
}

class AllLobes : public test::GpuTest {};

// Measured (32x32, 8x8-pixel blocks): the path tracer's two seeds differ by 0.3 % in the mean,
// 1.2e-4 in block relMSE and 5 % in the caustic's 5x5 window; the final gather with the full BSDF
// at every gather hit is 0.5 % off (relMSE 2e-4, caustic +1 %), the progressive (SPPM) estimate
// 0.9 % (1.4e-4, caustic -1.4 %). Tolerances: 2.5 % on the mean, 0.002 in block relMSE and 15 %
// on the caustic, several times that noise. With photons absorbed where they would pass the rough
// glass (a deliberate break in path_vertex.glsl, tried once) the caustic window came out 35 % and
// 41 % dark while the means moved only -0.5 % and -2.3 %: the caustic check is what sees it.
// With radiance photons (the final gather's default) the estimate is 4.6 % dark: a gather ray that
// ends on a surface reads its precomputed irradiance through diffuseReflectance, which leaves out
// the glossy lobes (docs/materials.md), and here the rough gold box is almost all glossy. That
// design bias is held to at most 8 % darker, never brighter.
TEST_F(AllLobes, PathTracerAndPhotonIntegratorsAgree) {
    const Scene scene = allLobesScene();
    Renderer renderer(test::gpu(), scene);
    const auto seconds = [start = std::chrono::steady_clock::now()] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const ImageRgb reference = renderer.render<PathIntegrator>(frame(256, 1)).image;
    const ImageRgb otherSeed = renderer.render<PathIntegrator>(frame(256, 2)).image;
    std::printf("path tracer: %.1f s\n", seconds());
    PhotonIntegratorSettings p;
    p.globalPaths = 100000;
    p.causticPaths = 100000;
    p.gatherRays = 1;
    const ImageRgb radiancePhotons = renderer.render<PhotonIntegrator>(frame(32, 3), p).image;
    p.radiancePhotonStride = 0;  // the full BSDF and k nearest photons at every gather hit
    const ImageRgb finalGather = renderer.render<PhotonIntegrator>(frame(32, 3), p).image;
    std::printf("final gathers: %.1f s\n", seconds());
    PhotonIntegratorSettings sppm;
    sppm.progressive = true;
    sppm.globalPaths = 20000;
    const ImageRgb progressive = renderer.render<ProgressivePhotonIntegrator>(frame(32, 4), sppm).image;
    std::printf("progressive: %.1f s\n", seconds());

    const double meanRef = meanLuminance(reference);
    const double noise = relativeMse(blockMeans(otherSeed, 8), blockMeans(reference, 8));
    std::printf("path tracer: mean %.4f, seed 2 mean %.4f, 8x8-block relMSE between seeds %.6f\n", meanRef,
                meanLuminance(otherSeed), noise);
    EXPECT_NEAR(meanLuminance(otherSeed), meanRef, 0.01 * meanRef) << "the reference's own noise";
    const glm::vec2 caustic = causticPixel(scene);
    const double causticRef = windowLuminance(reference, caustic);
    std::printf("caustic at pixel (%.1f, %.1f): %.4f, seed 2 %.4f\n", caustic.x, caustic.y, causticRef,
                windowLuminance(otherSeed, caustic));
    for (const auto& [name, image] : {std::pair{"photon (final gather, full BSDF at gather hits)", &finalGather},
                                      std::pair{"photon (progressive)", &progressive},
                                      std::pair{"photon (final gather, radiance photons)", &radiancePhotons}}) {
        const double err = relativeMse(blockMeans(*image, 8), blockMeans(reference, 8));
        const double mean = meanLuminance(*image);
        const double causticSeen = windowLuminance(*image, caustic);
        std::printf("%s: mean %.4f (%+.2f %%), 8x8-block relMSE %.6f, caustic %.4f (%+.2f %%)\n", name, mean,
                    100.0 * (mean / meanRef - 1.0), err, causticSeen, 100.0 * (causticSeen / causticRef - 1.0));
        if (image == &radiancePhotons) {
            EXPECT_GT(mean, 0.92 * meanRef) << name;
            EXPECT_LT(mean, 1.005 * meanRef) << name;
            continue;
        }
        EXPECT_NEAR(mean, meanRef, 0.025 * meanRef) << name;
        EXPECT_LT(err, 0.002) << name;
        EXPECT_NEAR(causticSeen, causticRef, 0.15 * causticRef) << name << ": the rough glass's caustic";
    }
}

}  // namespace
}  // namespace vkp
