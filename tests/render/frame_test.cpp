// Camera resolution: the default framing of scenes without a camera (every bounding-box corner
// inside the image, tightly, for boxes of many shapes and images of many aspects) and the
// --look-from / --look-at / --fov override.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "gpu_scene/scene_buffers.h"
#include "render/frame.h"
#include "util/errors.h"

namespace vkp {
namespace {

struct Projection {
    double x = 0.0, y = 0.0;  // -1..1 across the image (x right, y up)
    double depth = 0.0;       // along the view direction
};

// A point as the camera rays see it (makeGpuCamera is what the shaders get).
Projection project(const gpu::GpuCamera& c, glm::vec3 p) {
    const glm::dvec3 d = glm::dvec3(p) - glm::dvec3(c.position);
    Projection out;
    out.depth = glm::dot(d, glm::dvec3(c.forward));
    out.x = glm::dot(d, glm::dvec3(c.right)) / (out.depth * c.tanHalfFovY * c.aspect);
    out.y = glm::dot(d, glm::dvec3(c.up)) / (out.depth * c.tanHalfFovY);
    return out;
}

glm::vec3 corner(const Bounds& b, int i) {
    return {i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z};
}

std::string describe(const Bounds& b, float aspect) {
    return "box (" + std::to_string(b.min.x) + ", " + std::to_string(b.min.y) + ", " + std::to_string(b.min.z) + ") - (" +
           std::to_string(b.max.x) + ", " + std::to_string(b.max.y) + ", " + std::to_string(b.max.z) +
           "), aspect " + std::to_string(aspect);
}

TEST(Framing, EveryCornerInsideTheImageAndTheBoxFillsIt) {
    const Bounds boxes[] = {
        {glm::vec3(-1, 0, -1), glm::vec3(1, 2, 1)},            // the Cornell box
        {glm::vec3(0), glm::vec3(10, 1, 1)},                   // a long bar along X
        {glm::vec3(-0.1f, -20, 5), glm::vec3(0.1f, 1, 6)},     // a tall thin post, off the origin
        {glm::vec3(-5, 0, -5), glm::vec3(5, 0, 5)},            // a flat plate on the ground (no Y extent)
        {glm::vec3(-3, -2, 0), glm::vec3(3, 2, 0)},            // a flat panel facing +Z (no Z extent)
        {glm::vec3(2, 0, 0), glm::vec3(2, 0, 7)},              // a line along Z
        {glm::vec3(1000, 1000, 1000), glm::vec3(1000.5f, 1001, 1000.2f)},  // small and far away
        {glm::vec3(-1e-4f), glm::vec3(1e-4f)},                 // tiny
    };
    for (const Bounds& box : boxes)
        for (const float aspect : {1.0f, 16.0f / 9.0f, 1.0f / 3.0f, 4.0f}) {
            const uint32_t height = 300, width = uint32_t(std::lround(height * aspect));
            const Camera camera = framingCamera(box, float(width) / float(height));
            const gpu::GpuCamera c = makeGpuCamera(camera, width, height);
            double widest = 0.0;
            for (int i = 0; i < 8; ++i) {
                const Projection p = project(c, corner(box, i));
                ASSERT_GT(p.depth, 0.0) << describe(box, aspect) << ", corner " << i;
                EXPECT_LE(std::abs(p.x), kFramingFill + 1e-4) << describe(box, aspect) << ", corner " << i;
                EXPECT_LE(std::abs(p.y), kFramingFill + 1e-4) << describe(box, aspect) << ", corner " << i;
                widest = std::max({widest, std::abs(p.x), std::abs(p.y)});
            }
            // Exactly framed: the outermost corner touches the margin (no needless distance).
            EXPECT_NEAR(widest, kFramingFill, 1e-3) << describe(box, aspect);
            // A three-quarter view from the +X, +Y, +Z side, looking at the centre.
            EXPECT_LT(camera.forward.x, 0.0f);
            EXPECT_LT(camera.forward.y, 0.0f);
            EXPECT_LT(camera.forward.z, 0.0f);
            const Projection centre = project(c, box.center());
            EXPECT_NEAR(centre.x, 0.0, 1e-4) << describe(box, aspect);
            EXPECT_NEAR(centre.y, 0.0, 1e-4) << describe(box, aspect);
            EXPECT_NEAR(camera.yfov, kFramingYfov, 1e-7f);
        }
}

TEST(Framing, DegenerateBoxesStillGiveAView) {
    for (const Bounds& box : {Bounds{}, Bounds{glm::vec3(3, 4, 5), glm::vec3(3, 4, 5)}}) {
        const Camera camera = framingCamera(box, 1.0f);
        const glm::vec3 centre = box.empty() ? glm::vec3(0.0f) : box.center();
        const float distance = glm::distance(camera.position, centre);
        EXPECT_TRUE(std::isfinite(distance));
        EXPECT_GT(distance, 0.0f);
        EXPECT_NEAR(glm::length(camera.forward), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::normalize(centre - camera.position), camera.forward), 1.0f, 1e-5f);
    }
    // An empty box frames the unit cube at the origin.
    const Camera empty = framingCamera(Bounds{}, 1.0f);
    const gpu::GpuCamera c = makeGpuCamera(empty, 64, 64);
    for (int i = 0; i < 8; ++i) {
        const Projection p = project(c, corner(Bounds{glm::vec3(-0.5f), glm::vec3(0.5f)}, i));
        EXPECT_LE(std::max(std::abs(p.x), std::abs(p.y)), kFramingFill + 1e-4);
    }
}

TEST(Framing, AWiderFieldOfViewComesCloser) {
    const Bounds box{glm::vec3(-1), glm::vec3(1)};
    const float narrow = glm::length(framingCamera(box, 1.0f, glm::radians(20.0f)).position);
    const float wide = glm::length(framingCamera(box, 1.0f, glm::radians(90.0f)).position);
    EXPECT_GT(narrow, 2.0f * wide);
}

Scene sceneWith(const Bounds& bounds, bool withCamera) {
    Scene scene;
    scene.bounds = bounds;
    if (withCamera) {
        Camera c;
        c.name = "file";
        c.position = glm::vec3(0, 1, 10);
        c.yfov = 0.5f;
        scene.cameras.push_back(c);
    }
    return scene;
}

TEST(ViewOverride, ChangesWhicheverCameraIsChosen) {
    const Bounds box{glm::vec3(-1, 0, -1), glm::vec3(1, 2, 1)};
    for (const bool withCamera : {true, false}) {
        const Scene scene = sceneWith(box, withCamera);
        const Camera base = chooseCamera(scene, -1, 1.5f);
        EXPECT_EQ(base.name, withCamera ? "file" : "framing");
        EXPECT_EQ(base.position, withCamera ? glm::vec3(0, 1, 10) : framingCamera(box, 1.5f).position);

        ViewOverride fov;
        fov.fovDegrees = 60.0f;
        const Camera wider = chooseCamera(scene, -1, 1.5f, fov);
        EXPECT_FLOAT_EQ(wider.yfov, glm::radians(60.0f));
        EXPECT_EQ(wider.forward, base.forward);
        if (withCamera) EXPECT_EQ(wider.position, base.position);  // --fov alone keeps the file camera's place
        else EXPECT_EQ(wider.position, framingCamera(box, 1.5f, glm::radians(60.0f)).position);  // the framing refits

        ViewOverride both;
        both.lookFrom = glm::vec3(5, 5, 5);
        both.lookAt = glm::vec3(0, 1, 0);
        const Camera aimed = chooseCamera(scene, -1, 1.5f, both);
        EXPECT_EQ(aimed.position, glm::vec3(5, 5, 5));
        EXPECT_NEAR(glm::distance(aimed.forward, glm::normalize(glm::vec3(-5, -4, -5))), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(aimed.forward, aimed.up), 0.0f, 1e-6f);
        EXPECT_GT(aimed.up.y, 0.0f);
        EXPECT_EQ(aimed.yfov, base.yfov);  // without --fov the chosen camera's

        ViewOverride from;
        from.lookFrom = glm::vec3(0, 10, 0.5f);
        const Camera fromOnly = chooseCamera(scene, -1, 1.0f, from);  // looks at the bounds' centre
        EXPECT_NEAR(glm::dot(fromOnly.forward, glm::normalize(box.center() - from.lookFrom.value())), 1.0f, 1e-6f);

        ViewOverride at;
        at.lookAt = glm::vec3(1, 0, 1);
        const Camera atOnly = chooseCamera(scene, -1, 1.0f, at);  // turns where it stands
        EXPECT_EQ(atOnly.position, base.position);
        EXPECT_NEAR(glm::dot(atOnly.forward, glm::normalize(glm::vec3(1, 0, 1) - base.position)), 1.0f, 1e-6f);
    }
}

TEST(ViewOverride, StraightDownKeepsXToTheRight) {
    ViewOverride down;
    down.lookFrom = glm::vec3(0, 10, 0);
    down.lookAt = glm::vec3(0, 0, 0);
    const Camera c = chooseCamera(sceneWith(Bounds{glm::vec3(-1), glm::vec3(1)}, false), -1, 1.0f, down);
    const gpu::GpuCamera g = makeGpuCamera(c, 8, 8);
    EXPECT_NEAR(glm::distance(g.right, glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(g.forward, glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
}

TEST(ViewOverride, BadValuesNameTheirFlag) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const auto expectRefused = [](const ViewOverride& v, const std::string& flag) {
        try {
            v.check();
            ADD_FAILURE() << "not refused: " << flag;
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(flag, 0), 0u) << e.what();
        }
    };
    for (const float bad : {nan, inf, -inf}) {
        expectRefused(ViewOverride{glm::vec3(0, bad, 0), std::nullopt, std::nullopt}, "--look-from");
        expectRefused(ViewOverride{std::nullopt, glm::vec3(bad, 0, 0), std::nullopt}, "--look-at");
    }
    for (const float fov : {0.0f, -10.0f, 180.0f, 200.0f, nan, inf})
        expectRefused(ViewOverride{std::nullopt, std::nullopt, fov}, "--fov");
    expectRefused(ViewOverride{glm::vec3(1, 2, 3), glm::vec3(1, 2, 3), std::nullopt}, "--look-from and --look-at");
    EXPECT_NO_THROW((ViewOverride{glm::vec3(1, 2, 3), glm::vec3(1, 2, 4), 179.0f}.check()));
    EXPECT_NO_THROW((ViewOverride{std::nullopt, std::nullopt, 0.01f}.check()));

    // Known only once the camera is resolved: --look-from at the centre it would look at.
    ViewOverride atCentre;
    atCentre.lookFrom = glm::vec3(0, 1, 0);
    EXPECT_THROW(chooseCamera(sceneWith(Bounds{glm::vec3(-1, 0, -1), glm::vec3(1, 2, 1)}, false), -1, 1.0f, atCentre),
                 InputError);
    EXPECT_THROW(chooseCamera(sceneWith(Bounds{}, true), 1), InputError);  // --camera 1 of 1
}

TEST(ViewOverride, FrameSettingsCheckIncludesIt) {
    FrameSettings settings;
    settings.view.fovDegrees = 0.0f;
    EXPECT_THROW(settings.check(), InputError);
    settings.view.fovDegrees = 50.0f;
    EXPECT_NO_THROW(settings.check());
    // makeFrame applies it with the image's aspect ratio.
    settings.width = 640;
    settings.height = 320;
    const Scene scene = sceneWith(Bounds{glm::vec3(-1), glm::vec3(1)}, false);
    const Frame frame = makeFrame(scene, settings);
    EXPECT_FLOAT_EQ(frame.camera.yfov, glm::radians(50.0f));
    EXPECT_EQ(frame.camera.position, framingCamera(scene.bounds, 2.0f, glm::radians(50.0f)).position);
}

}  // namespace
}  // namespace vkp
