// The raster pass's light skipping (lights/light_reach.h, docs/light-sampling.md "Raster pass"):
// with --light-sampler photon, lights whose primary photons reach no cell the camera sees are
// left out. The rule is statistical, so the tests check it where the answer is known: in the
// hundred rooms the lights of rooms the camera cannot see are skipped and every skipped light is
// in fact hidden from every visible point tested (host shadow rays); behind the door slit, the one
// light whose light reaches the camera's room only through the slit is kept.
#include <gtest/gtest.h>

#include "bvh/scene_bvh.h"
#include "support/gpu_test_support.h"
#include "render/frame.h"
#include "lights/light_reach.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"

namespace vkp {
namespace {

class LightReachTest : public test::GpuTest {};

struct ReachResult {
    std::vector<bool> keep;
    uint32_t kept = 0;
};

ReachResult reachOf(const Renderer& renderer, const Scene& scene) {
    FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    const Frame frame = makeFrame(scene, settings);
    ReachResult r;
    r.keep = lightsReachingView(renderer.gpuScene().arrays(), *renderer.lightReach(), frame.gpuCamera, settings.width,
                                settings.height);
    for (bool k : r.keep) r.kept += k;
    return r;
}

LightSampling photonSampling(uint32_t photons) {
    LightSampling s;
    s.sampler = LightSampler::Photon;
    s.cellPhotons = photons;
    return s;
}

TEST_F(LightReachTest, RoomsTheCameraCannotSeeAreSkippedAndReallyHidden) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/rooms-10x10.gltf");
    const Renderer renderer(test::gpu(), scene, photonSampling(200000));
    ASSERT_TRUE(renderer.lightReach());
    const ReachResult r = reachOf(renderer, scene);
    const SceneArrays& a = renderer.gpuScene().arrays();
    ASSERT_EQ(r.keep.size(), 200u);  // 100 lights of two triangles
    EXPECT_GT(r.kept, 2u);
    EXPECT_LT(r.kept, 100u) << "most rooms are out of the camera's sight";

    // The camera's room (5, 5) = [0, 4] x [0, 4]: its light (centred at (2, 2.49, 2)) is kept.
    const gpu::BvhArrays bvh = a.bvhArrays();
    std::vector<glm::vec3> lightCentre(a.lights.size());
    for (size_t i = 0; i < a.lights.size(); ++i) {
        const gpu::GpuTriangle& t = a.triangles[a.lights[i].triangle];
        lightCentre[i] = (glm::vec3(t.v0) + glm::vec3(t.v1) + glm::vec3(t.v2)) / 3.0f;
        if (glm::distance(glm::vec2(lightCentre[i].x, lightCentre[i].z), glm::vec2(2.0f, 2.0f)) < 0.5f) {
            EXPECT_TRUE(r.keep[i]) << "the light of the camera's room";
        }
    }

    // Every skipped light is hidden from the points the camera sees (16 x 12 pixel centres; three
    // points on each light triangle): skipping it loses nothing there.
    FrameSettings settings;
    settings.width = 64;
    settings.height = 48;
    const gpu::GpuCamera camera = makeFrame(scene, settings).gpuCamera;
    uint32_t visiblePoints = 0, skippedLights = 0;
    for (size_t i = 0; i < a.lights.size(); ++i) skippedLights += !r.keep[i];
    ASSERT_GT(skippedLights, 100u);
    for (uint32_t y = 0; y < 12; ++y) {
        for (uint32_t x = 0; x < 16; ++x) {
            const glm::vec2 pixel((x + 0.5f) * 4.0f, (y + 0.5f) * 4.0f);
            const glm::vec3 org = gpu::cameraRayOrigin(camera, settings.width, settings.height, pixel);
            const glm::vec3 dir = gpu::cameraRayDirection(camera, settings.width, settings.height, pixel);
            const RayHit hit = closestHit(bvh, org, dir, 1e30f);
            if (!hit.hit) continue;
            ++visiblePoints;
            const glm::vec3 p = org + (hit.t - 1e-3f) * dir;
            for (size_t i = 0; i < a.lights.size(); ++i) {
                if (r.keep[i]) continue;
                const gpu::GpuTriangle& t = a.triangles[a.lights[i].triangle];
                for (const glm::vec3 corner : {glm::vec3(t.v0), glm::vec3(t.v1), glm::vec3(t.v2)}) {
                    const glm::vec3 q = glm::mix(lightCentre[i], corner, 0.9f);
                    const float distance = glm::length(q - p);
                    EXPECT_TRUE(anyHit(bvh, p, (q - p) / distance, distance * 0.999f))
                        << "skipped light " << i << " is visible from pixel (" << pixel.x << ", " << pixel.y << ")";
                }
            }
        }
    }
    EXPECT_GT(visiblePoints, 150u);
}

TEST_F(LightReachTest, TheLightBehindTheSlitIsKept) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/door-slit.gltf");
    const Renderer renderer(test::gpu(), scene, photonSampling(20000));
    const ReachResult r = reachOf(renderer, scene);
    ASSERT_EQ(r.keep.size(), 2u);  // one light square of two triangles, in the room the camera cannot see
    EXPECT_EQ(r.kept, 2u);
}

}  // namespace
}  // namespace vkp
