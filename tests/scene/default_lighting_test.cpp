// The default lighting rule (scene/environment.h, docs/environment.md): without --env the white
// sky is added to a scene whose emissive surfaces give under kMinEmitterShare of the light the
// sky would, never to a scene with punctual lights.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "scene/environment.h"
#include "scene/gltf_loader.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

void addTriangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material) {
    Triangle t;
    t.p[0] = a;
    t.p[1] = b;
    t.p[2] = c;
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    t.n[0] = t.n[1] = t.n[2] = n;
    t.material = material;
    scene.triangles.push_back(t);
    for (const glm::vec3& p : {a, b, c}) scene.bounds.grow(p);
}

// A grey cube [-1, 1]^3 (its faces as single triangles are enough for the bounds) and on its +Z
// face an emissive square of side `side` and radiance `radiance` (single-sided, facing +Z).
Scene cubeWithLamp(float side, float radiance) {
    Scene scene;
    Material grey;
    grey.baseColor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    Material lamp;
    lamp.emissive = glm::vec3(radiance);
    scene.materials = {grey, lamp};
    addTriangle(scene, {-1, -1, -1}, {1, 1, -1}, {1, -1, -1}, 0);
    addTriangle(scene, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, 0);
    const float h = 0.5f * side;
    addTriangle(scene, {-h, -h, 1}, {h, -h, 1}, {h, h, 1}, 1);
    addTriangle(scene, {-h, -h, 1}, {h, h, 1}, {-h, h, 1}, 1);
    return scene;
}

// Emitters pi L s^2 against the sky's 4 pi^2 r^2 with r = sqrt(3) (half the cube's diagonal).
double expectedShare(double side, double radiance) {
    const double emitters = M_PI * radiance * side * side;
    const double sky = 4.0 * M_PI * M_PI * 3.0;
    return emitters / (emitters + sky);
}

TEST(DefaultLighting, TheEmittersShareIsTheirPowerAgainstTheSkys) {
    for (const float side : {0.25f, 0.5f, 1.5f})
        for (const float radiance : {1.0f, 40.0f}) {
            const EmitterShare share = emitterShare(cubeWithLamp(side, radiance));
            EXPECT_NEAR(share.emitterPower, M_PI * radiance * side * side, 1e-4 * share.emitterPower);
            EXPECT_NEAR(share.skyPower, 12.0 * M_PI * M_PI, 1e-4 * share.skyPower);
            EXPECT_NEAR(share.share(), expectedShare(side, radiance), 1e-6) << side << " " << radiance;
        }
    EXPECT_EQ(emitterShare(cubeWithLamp(0.0f, 0.0f)).share(), 0.0);
}

TEST(DefaultLighting, SmallEmissiveDetailsGetTheSkyRealLampsDoNot) {
    // Side 0.5 at radiance 1: 0.66 % of the sky's light, a detail: the sky is added.
    ASSERT_LT(expectedShare(0.5, 1.0), kMinEmitterShare);
    Scene detail = cubeWithLamp(0.5f, 1.0f);
    std::string note;
    applyEnvironment(detail, {}, note);
    EXPECT_TRUE(detail.environment.present);
    EXPECT_EQ(detail.environment.radiance, glm::vec3(1.0f));
    EXPECT_NE(note.find("0.66 %"), std::string::npos) << note;

    // The same square at radiance 40 (21 %) lights the scene: no sky.
    ASSERT_GT(expectedShare(0.5, 40.0), kMinEmitterShare);
    Scene lamp = cubeWithLamp(0.5f, 40.0f);
    note.clear();
    applyEnvironment(lamp, {}, note);
    EXPECT_FALSE(lamp.environment.present);
    EXPECT_TRUE(note.empty()) << note;

    // A punctual light, however faint (a photometric 1 cd is 1/683 W/sr), means the scene is lit
    // as its author lit it; --exposure auto shows it.
    Scene punctual = cubeWithLamp(0.5f, 1.0f);
    PunctualLight faint;
    faint.intensity = glm::vec3(1.0f / 683.0f);
    punctual.lights.push_back(faint);
    applyEnvironment(punctual, {}, note);
    EXPECT_FALSE(punctual.environment.present);

    // --env 0: the emitters alone, as before; --env adds a sky to any scene.
    EnvironmentSettings none;
    none.value = "0";
    Scene alone = cubeWithLamp(0.5f, 1.0f);
    applyEnvironment(alone, none, note);
    EXPECT_FALSE(alone.environment.present);
    EnvironmentSettings sky;
    sky.value = "0.5";
    applyEnvironment(lamp, sky, note);
    EXPECT_TRUE(lamp.environment.present);
    EXPECT_EQ(lamp.environment.radiance, glm::vec3(0.5f));
}

TEST(DefaultLighting, TheShippedScenesWithLampsKeepTheirOwnLight) {
    for (const char* name : {"cornell-box", "cornell-ceiling", "cornell-glass", "cubicles-1024", "door-slit",
                             "hall-moving", "rooms-10x10"}) {
        Scene scene = loadGltf(fs::path(VKPHOTON_SCENES) / (std::string(name) + ".gltf"));
        const double share = emitterShare(scene).share();
        EXPECT_GT(share, 2.0 * kMinEmitterShare) << name;  // a margin: no scene near the threshold
        std::string note;
        applyEnvironment(scene, {}, note);
        EXPECT_FALSE(scene.environment.present) << name << ": " << note;
    }
}

}  // namespace
}  // namespace vkp
