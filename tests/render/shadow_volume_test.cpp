// Raster shadow volumes against ray tracing: the RGBA shadow mask of host/passes/shadow_volume_pass
// must equal the visibility that the path tracer's shadow rays (tests/shaders/
// shadow_visibility_test.comp, the project's BVH) find for the same pixel centres on >= 99.5 % of
// the pixels where the mask matters; differences may only sit on shadow edges. Scenes: closed and
// open meshes built in code, the camera inside a shadow volume, and the shipped scenes with point
// lights added. Also host-side edge adjacency (closed 2-manifold vs per-triangle fallback).
#include <bit>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "passes/raster_lights.h"
#include "gpu_scene/scene_buffers.h"
#include "passes/shadow_triangles.h"
#include "passes/shadow_volume_pass.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "shaders/test_kernels.glsl"
#include "support/test_scenes.h"
#include "vk/kernel.h"

namespace vkp {
namespace {

struct MaskAgreement {
    uint64_t relevant = 0;  // (pixel, light) pairs where the visible surface faces the light
    uint64_t agree = 0;
    uint64_t shadowed = 0;  // of the relevant pairs, traced as occluded
    uint64_t offEdge = 0;   // disagreements with no shadow edge or crease in the 3x3 neighbourhood
    double fraction() const { return relevant ? double(agree) / double(relevant) : 0.0; }
};

// Triangles a and b (BVH order) lie in one plane: a flat surface, not a crease.
bool samePlane(const std::vector<gpu::GpuTriangle>& tris, uint32_t a, uint32_t b) {
    if (a == b) return true;
    if (a >= tris.size() || b >= tris.size()) return false;
    auto normal = [&](uint32_t t) {
        const glm::vec3 v0(tris[t].v0), v1(tris[t].v1), v2(tris[t].v2);
        return glm::normalize(glm::cross(v1 - v0, v2 - v0));
    };
    const glm::vec3 na = normal(a), nb = normal(b);
    const glm::vec3 pa(tris[a].v0), pb(tris[b].v0);
    return std::abs(glm::dot(na, nb)) > 0.9999f && std::abs(glm::dot(na, pb - pa)) < 1e-4f;
}

MaskAgreement compareMaskWithRays(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height,
                                  VolumeGeometry geometry = VolumeGeometry::Compute) {
    vk::Context& context = test::gpu();
    const SceneArrays arrays = buildSceneArrays(scene);
    const SceneBuffers buffers(context, arrays);
    const auto lights = buildRasterLights(arrays, 0);
    EXPECT_LE(lights.size(), 32u);
    ShadowVolumePass pass(context, arrays.triangles, lights, width, height, geometry);
    const gpu::GpuCamera gpuCamera = makeGpuCamera(camera, width, height);
    const float near = 1.0e-3f * std::max(1.0f, glm::length(scene.bounds.extent()));
    context.submitAndWait([&](VkCommandBuffer cmd) { pass.record(cmd, gpuCamera, near); });
    const auto masks = pass.masks().download<uint32_t>();

    const uint64_t pixels = uint64_t(width) * height;
    vk::Buffer out(context, "visibility", pixels * 3 * sizeof(uint32_t), vk::kStorageUsage);
    vk::Kernel<gpu::ShadowTestKernel> kernel(context);
    kernel.bind(buffers.bindings());
    kernel.bind(gpu::kShadowTestLightBinding, pass.lights());
    kernel.bind(gpu::kShadowTestOutputBinding, out);
    gpu::RasterDirectParams params{};
    params.camera = gpuCamera;
    params.width = width;
    params.height = height;
    params.lightCount = static_cast<uint32_t>(lights.size());
    context.submitAndWait([&](VkCommandBuffer cmd) {
        kernel.record(cmd, pixels, params);
        vk::computeBarrier(cmd);
    });
    const auto traced = out.download<uint32_t>();

    MaskAgreement result;
    for (uint64_t p = 0; p < pixels; ++p)
        for (uint32_t k = 0; k < lights.size(); ++k) {
            if (!((traced[3 * p + 1] >> k) & 1u)) continue;
            const uint32_t word = masks[(k / gpu::kLightsPerMaskPass) * pixels + p];
            const bool rasterLit = ((word >> (8 * (k % gpu::kLightsPerMaskPass))) & 0xffu) != 0;
            const bool tracedLit = (traced[3 * p] >> k) & 1u;
            ++result.relevant;
            result.agree += rasterLit == tracedLit;
            result.shadowed += !tracedLit;
            if (rasterLit == tracedLit) continue;
            // A disagreement is on an edge when a neighbour's traced visibility differs, the
            // neighbour's surface does not face the light, or it lies in another plane (a crease
            // such as a room corner, where the pixel centre is within rounding of both surfaces).
            const int x = int(p % width), y = int(p / width);
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= int(width) || ny >= int(height)) { edge = true; continue; }
                    const uint64_t q = uint64_t(ny) * width + nx;
                    if (!((traced[3 * q + 1] >> k) & 1u) || (((traced[3 * q] >> k) & 1u) != uint32_t(tracedLit)) ||
                        !samePlane(arrays.triangles, traced[3 * p + 2], traced[3 * q + 2]))
                        edge = true;
                }
            result.offEdge += !edge;
        }
    return result;
}

void expectAgreement(const MaskAgreement& m, const std::string& what) {
    fmt::print("{}: {} of {} (pixel, light) pairs agree ({:.3f} %), {} traced as shadowed, {} off edges\n", what,
               m.agree, m.relevant, 100.0 * m.fraction(), m.shadowed, m.offEdge);
    EXPECT_EQ(m.offEdge, 0u) << what << ": disagreements away from shadow and geometry edges";
    EXPECT_GT(m.relevant, 0u) << what;
    EXPECT_GE(m.fraction(), 0.995) << what << ": raster and traced visibility agree on " << m.agree << " of "
                                   << m.relevant << " (pixel, light) pairs";
    // The scenes are built so both outcomes occur: a mask of all ones (or zeros) must not pass.
    EXPECT_GT(m.shadowed, m.relevant / 50) << what << ": too few shadowed pixels for a meaningful test";
    EXPECT_LT(m.shadowed, m.relevant - m.relevant / 50) << what << ": too few lit pixels for a meaningful test";
}

Scene cubeOnFloor(bool openBox) {
    Scene scene = test::shadowTestScene();
    test::addQuad(scene, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4});
    test::addBox(scene, {-0.5f, 0.5f, -0.5f}, {0.5f, 1.5f, 0.5f}, openBox);
    test::addPointLight(scene, {0.3f, 3.0f, 0.2f}, glm::vec3(10.0f));
    test::addPointLight(scene, {-2.0f, 2.5f, 1.0f}, glm::vec3(10.0f));
    test::addPointLight(scene, {1.5f, 2.0f, -1.5f}, glm::vec3(10.0f));
    return scene;
}

TEST(ShadowTriangles, ClosedBoxIsManifoldOpenMeshesFallBack) {
    Scene closed = test::shadowTestScene();
    test::addBox(closed, glm::vec3(0.0f), glm::vec3(1.0f));
    const SceneArrays a = buildSceneArrays(closed);
    const ShadowTriangles s = buildShadowTriangles(a.triangles);
    EXPECT_EQ(s.closedTriangles, 12u);
    EXPECT_EQ(s.openTriangles, 0u);
    for (const auto& t : s.triangles) {
        for (uint32_t n : {t.neighbor0, t.neighbor1, t.neighbor2}) {
            ASSERT_LT(n, 12u);
            EXPECT_NE(&s.triangles[n], &t);
        }
    }

    Scene open = test::shadowTestScene();
    test::addBox(open, glm::vec3(0.0f), glm::vec3(1.0f), true);
    test::addBox(open, glm::vec3(2.0f), glm::vec3(3.0f));  // a separate closed box stays closed
    const ShadowTriangles o = buildShadowTriangles(buildSceneArrays(open).triangles);
    EXPECT_EQ(o.openTriangles, 10u);
    EXPECT_EQ(o.closedTriangles, 12u);

    // A flipped triangle makes its whole component inconsistent: per-triangle volumes.
    Scene flipped = test::shadowTestScene();
    test::addBox(flipped, glm::vec3(0.0f), glm::vec3(1.0f));
    std::swap(flipped.triangles[3].p[1], flipped.triangles[3].p[2]);
    const ShadowTriangles f = buildShadowTriangles(buildSceneArrays(flipped).triangles);
    EXPECT_EQ(f.openTriangles, 12u);
}

class RasterShadowMask : public test::GpuTest {};

TEST_F(RasterShadowMask, ClosedCubeMatchesRayTracedVisibility) {
    expectAgreement(compareMaskWithRays(cubeOnFloor(false), test::lookAt({0.5f, 3.0f, 4.5f}, {0, 0.3f, 0}), 96, 96),
                    "closed cube");
}

TEST_F(RasterShadowMask, CameraInsideShadowVolume) {
    // Between the cube and the floor, under the first light: the camera is inside that light's
    // volume (z-pass would be wrong here; z-fail must not be).
    const Scene scene = cubeOnFloor(false);
    const Camera camera = test::lookAt({0.1f, 0.3f, 0.1f}, {1.5f, 0.0f, 1.2f}, 1.4f);
    expectAgreement(compareMaskWithRays(scene, camera, 96, 96), "camera inside a shadow volume");
}

TEST_F(RasterShadowMask, OpenMeshMatchesRayTracedVisibility) {
    // A box without its top (open, so per-triangle volumes) and a single floating quad.
    Scene scene = cubeOnFloor(true);
    test::addQuad(scene, {1.0f, 1.0f, 1.0f}, {2.0f, 1.0f, 1.0f}, {2.0f, 1.2f, 2.0f}, {1.0f, 1.2f, 2.0f});
    expectAgreement(compareMaskWithRays(scene, test::lookAt({1.0f, 3.5f, 4.0f}, {0.3f, 0.3f, 0.3f}), 96, 96),
                    "open mesh");
}

TEST_F(RasterShadowMask, CameraInsideOpenMeshVolume) {
    Scene scene = cubeOnFloor(true);
    const Camera camera = test::lookAt({0.1f, 0.3f, 0.1f}, {-1.5f, 0.0f, 1.2f}, 1.4f);
    expectAgreement(compareMaskWithRays(scene, camera, 96, 96), "camera inside an open mesh's volume");
}

TEST_F(RasterShadowMask, SpotAndDirectionalLightsMatchRayTracedVisibility) {
    // Directional light: volumes extrude towards a point at infinity (w = 0), the back cap
    // degenerates to that point. Spot light: a point light for the volumes, its cone only in the
    // lighting.
    Scene scene = cubeOnFloor(false);
    scene.lights.clear();
    test::addSunAndSpot(scene, glm::vec3(2.0f), glm::vec3(10.0f));
    expectAgreement(compareMaskWithRays(scene, test::lookAt({0.5f, 3.0f, 4.5f}, {0, 0.3f, 0}), 96, 96),
                    "spot and directional lights");
}

class ShippedSceneShadowMask : public test::GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(ShippedSceneShadowMask, PointLightsMatchRayTracedVisibility) {
    // The shipped scenes light with emissive triangles; five point lights spread through the room
    // (two mask passes) exercise every RGBA channel.
    Scene scene = loadGltf(std::string(VKPHOTON_SCENES) + "/" + GetParam() + ".gltf");
    const glm::vec3 lo = scene.bounds.min, ext = scene.bounds.extent();
    const glm::vec3 at[5] = {{0.5f, 0.9f, 0.5f}, {0.2f, 0.7f, 0.3f}, {0.8f, 0.5f, 0.6f}, {0.3f, 0.3f, 0.7f}, {0.7f, 0.8f, 0.2f}};
    for (const glm::vec3& f : at) test::addPointLight(scene, lo + f * ext, glm::vec3(1.0f));
    const MaskAgreement m = compareMaskWithRays(scene, chooseCamera(scene, -1), 96, 96);
    fmt::print("{}: {} of {} agree, {} shadowed, {} off edges\n", GetParam(), m.agree, m.relevant, m.shadowed, m.offEdge);
    EXPECT_EQ(m.offEdge, 0u) << GetParam() << ": disagreements away from shadow and geometry edges";
    EXPECT_GT(m.relevant, 0u);
    EXPECT_GE(m.fraction(), 0.995) << GetParam() << ": agree on " << m.agree << " of " << m.relevant;
    EXPECT_GT(m.shadowed, 0u) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Shipped, ShippedSceneShadowMask,
                         ::testing::Values("cornell-box", "cornell-ceiling", "cornell-glass"),
                         [](const auto& info) {
                             std::string n = info.param;
                             for (char& ch : n) if (ch == '-') ch = '_';
                             return n;
                         });

}  // namespace
}  // namespace vkp
