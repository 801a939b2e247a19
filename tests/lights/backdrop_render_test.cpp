// Sky boxes rendered (docs/environment.md "Sky boxes"): inside an inward-facing box around the
// scene, lit by nothing but the default sky, the camera sees the box's walls lit by the sky (a
// Lambert wall of albedo 0.5 under radiance 1 shows 0.5, less the little the cube hides) and the
// cube as it looks without the box; from outside, the near wall's single-sided back face is
// culled and the camera sees the cube and the far wall's inside. Without the rule the box is closed and dark (the walls near 0).
#include <gtest/gtest.h>

#include "lights/default_lighting.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "support/gpu_test_support.h"
#include "support/sky_box_scenes.h"
#include "support/small_frame.h"
#include "support/test_scenes.h"

namespace vkp {
namespace {

class SkyBoxRender : public test::GpuTest {};

constexpr uint32_t kSize = 48;

Scene lit(test::SkyBoxOptions options, glm::vec3 eye) {
    Scene scene = test::skyBoxScene(options);
    std::string note;
    applyEnvironment(scene, EnvironmentSettings{}, note);
    scene.cameras.push_back(test::lookAt(eye, glm::vec3(0.0f)));
    return scene;
}

// Mean red of the pixels within `r` (a fraction of the half-size) of the centre, or outside it.
float meanOf(const ImageRgb& image, float r, bool inside) {
    double sum = 0.0;
    uint32_t n = 0;
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const float dx = (x + 0.5f) / image.width * 2.0f - 1.0f, dy = (y + 0.5f) / image.height * 2.0f - 1.0f;
            if ((std::max(std::abs(dx), std::abs(dy)) < r) != inside) continue;
            sum += image.pixels[3 * (size_t(y) * image.width + x)];
            ++n;
        }
    return n ? float(sum / n) : 0.0f;
}

ImageRgb pathTraced(const Scene& scene) {
    Renderer renderer(test::gpu(), scene);
    return renderer.render<PathIntegrator>(test::smallFrame(kSize, 32, 3)).image;
}

TEST_F(SkyBoxRender, TheSkyLightsTheSceneThroughItsSkyBox) {
    const glm::vec3 inside(0.0f, 0.0f, 8.0f);
    const Scene boxed = lit({}, inside);
    ASSERT_EQ(boxed.backdropNodes, std::vector<int>{0});
    const ImageRgb image = pathTraced(boxed);
    const ImageRgb alone = pathTraced(lit({.withBox = false}, inside));
    // The cube (the middle fifth of the frame) as without the box: the same paths, the same sky.
    const float cube = meanOf(image, 0.2f, true);
    EXPECT_GT(cube, 0.3f);
    EXPECT_NEAR(cube, meanOf(alone, 0.2f, true), 0.01f * cube);
    // The far wall beyond the cube (the frame's outer half): albedo 0.5 under the sky, minus the
    // few per cent of the sky the cube hides, plus what the cube reflects.
    const float wall = meanOf(image, 0.5f, false);
    EXPECT_GT(wall, 0.47f);
    EXPECT_LT(wall, 0.51f);
    EXPECT_NEAR(meanOf(alone, 0.5f, false), 1.0f, 1e-6f) << "without the box the camera sees the sky";
    // The box as an instance (its mesh's triangles carry the flag): the same image.
    const Scene instanced = lit({.instanced = true}, inside);
    ASSERT_EQ(instanced.backdropNodes, std::vector<int>{0});
    const ImageRgb instancedImage = pathTraced(instanced);
    EXPECT_NEAR(meanOf(instancedImage, 0.5f, false), wall, 0.01f * wall) << "instanced box";
    EXPECT_NEAR(meanOf(instancedImage, 0.2f, true), cube, 0.01f * cube) << "instanced box";

}

TEST_F(SkyBoxRender, FromOutsideTheNearWallIsCulled) {
    const glm::vec3 outside(0.0f, 0.0f, 30.0f);
    const ImageRgb image = pathTraced(lit({}, outside));
    const ImageRgb alone = pathTraced(lit({.withBox = false}, outside));
    EXPECT_NEAR(meanOf(image, 0.05f, true), meanOf(alone, 0.05f, true), 0.01f);
    // The near wall's back face is culled; beyond it the far wall's front, lit by the sky.
    const float wall = meanOf(image, 0.5f, false);
    EXPECT_GT(wall, 0.47f);
    EXPECT_LT(wall, 0.51f);
}

TEST_F(SkyBoxRender, ADoubleSidedBoxStaysClosed) {
    // Not a sky box: the sky cannot reach inside, the walls are dark.
    const Scene closed = lit({.doubleSided = true}, glm::vec3(0.0f, 0.0f, 8.0f));
    ASSERT_TRUE(closed.backdropNodes.empty());
    EXPECT_LT(meanOf(pathTraced(closed), 0.5f, false), 0.01f);
}

}  // namespace
}  // namespace vkp
