// The photon integrator's visible-point pass: emission plus next-event direct light at the first
// non-delta surface must equal, in the mean, the path tracer limited to one bounce (emission plus
// MIS-combined direct light) on a scene without delta surfaces; visible points lie behind glass.
#include <cmath>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "image/image.h"
#include "photon/visible_point_pass.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "shared/photon.glsl"
#include "support/small_frame.h"

namespace vkp {
namespace {

struct VisiblePointRun {
    double meanRadiance = 0.0;
    std::vector<gpu::GpuVisiblePoint> points;
};

VisiblePointRun runVisiblePoints(const Scene& scene, uint32_t size, uint32_t samples, uint32_t seed) {
    vk::Context& context = test::gpu();
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(context, arrays);
    const uint64_t pixels = uint64_t(size) * size;
    vk::Buffer film(context, "film", pixels * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Buffer points(context, "visible points", pixels * sizeof(gpu::GpuVisiblePoint), vk::kStorageUsage);
    vk::Buffer noRasterDirect(context, "no raster direct", 16, vk::kStorageUsage);
    VisiblePointPass pass(context, buffers, film, points, noRasterDirect);
    gpu::VisiblePointParams params{};
    params.camera = makeGpuCamera(chooseCamera(scene, -1), size, size);
    params.width = size;
    params.height = size;
    params.seed = seed;
    params.maxSpecularDepth = 16;
    params.lightCount = buffers.lightCount();
    context.submitAndWait([&](VkCommandBuffer cmd) {
        film.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
        for (uint32_t s = 0; s < samples; ++s) {
            params.sampleIndex = s;
            pass.record(cmd, params);
            vk::computeBarrier(cmd);
        }
        vk::computeToHostBarrier(cmd);
    });
    VisiblePointRun run;
    double sum = 0.0;
    for (const glm::vec4& v : film.download<glm::vec4>()) sum += (v.x + v.y + v.z) / (3.0 * v.w);
    run.meanRadiance = sum / pixels;
    run.points = points.download<gpu::GpuVisiblePoint>();
    return run;
}

class VisiblePoints : public test::GpuTest {};

TEST_F(VisiblePoints, DirectLightMatchesTheOneBouncePathTracer) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-box.gltf");
    constexpr int kSeeds = 4;
    double sumA = 0, sumSqA = 0, sumB = 0, sumSqB = 0;
    Renderer renderer(test::gpu(), scene);
    for (int seed = 0; seed < kSeeds; ++seed) {
        const double a = runVisiblePoints(scene, 32, 64, 10 + seed).meanRadiance;
        FrameSettings s = test::smallFrame(32, 64, 20 + seed);
        s.maxDepth = 1;
        const double b = meanValue(renderer.render<PathIntegrator>(s).image);
        sumA += a; sumSqA += a * a; sumB += b; sumSqB += b * b;
    }
    const double meanA = sumA / kSeeds, meanB = sumB / kSeeds;
    const double se = std::sqrt(std::max(0.0, sumSqA / kSeeds - meanA * meanA) / (kSeeds - 1) +
                                std::max(0.0, sumSqB / kSeeds - meanB * meanB) / (kSeeds - 1));
    EXPECT_NEAR(meanA, meanB, 5.0 * se + 0.01 * meanB) << "visible points " << meanA << ", path tracer " << meanB;
}

TEST_F(VisiblePoints, GlassIsSeenThroughAndAlmostEveryPixelHasAPoint) {
    const Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/cornell-glass.gltf");
    const auto run = runVisiblePoints(scene, 48, 1, 0);
    const glm::vec3 glassCenter(0.35f, 0.35f, 0.25f);  // scripts/make_scenes.py
    size_t valid = 0, onGlass = 0;
    for (uint32_t i = 0; i < run.points.size(); ++i) {
        const auto& p = run.points[i];
        EXPECT_EQ(p.pixel, i);
        if (!(p.flags & gpu::kVisiblePointValid)) continue;
        ++valid;
        // No visible point on the glass surface itself: it is purely specular.
        if (std::abs(glm::distance(p.position, glassCenter) - 0.35f) < 1e-3f) ++onGlass;
        EXPECT_NEAR(glm::length(gpu::decodeOctahedral(p.shadingNormal)), 1.0f, 1e-4f);
    }
    // The room is open towards the camera: only paths mirrored out of it by the chrome sphere
    // (or the glass) find no surface.
    EXPECT_GT(valid, run.points.size() * 9 / 10);
    EXPECT_LT(valid, run.points.size());
    EXPECT_EQ(onGlass, 0u);
}

}  // namespace
}  // namespace vkp
