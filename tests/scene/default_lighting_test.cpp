// The default lighting rule (lights/default_lighting.h, docs/environment.md): without --env the
// white sky is added to a scene whose emissive surfaces put under kMinEmitterShare of the light
// the sky would on its surfaces, never to a scene with punctual lights.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "lights/default_lighting.h"
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

// An axis-aligned square of half-size h at z, facing +Z (or -Z), as two triangles.
void addSquare(Scene& scene, float h, float z, bool facingMinusZ, uint32_t material) {
    if (facingMinusZ) {
        addTriangle(scene, {-h, -h, z}, {h, h, z}, {h, -h, z}, material);
        addTriangle(scene, {-h, -h, z}, {-h, h, z}, {h, h, z}, material);
    } else {
        addTriangle(scene, {-h, -h, z}, {h, -h, z}, {h, h, z}, material);
        addTriangle(scene, {-h, -h, z}, {h, h, z}, {-h, h, z}, material);
    }
}

// A closed grey cube [-1, 1]^3 and an emissive square of side `side` and radiance `radiance`
// (single-sided): inside, just under the +Z face, facing down into the cube (a lamp in a room:
// all its light lands), or on the +Z face facing out (`outside`: a glowing detail whose light all
// leaves the scene).
Scene cubeWithLamp(float side, float radiance, bool outside = false) {
    Scene scene;
    Material grey;
    grey.baseColor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    Material lamp;
    lamp.emissive = glm::vec3(radiance);
    scene.materials = {grey, lamp};
    const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    for (const auto& f : faces) {
        addTriangle(scene, c[f[0]], c[f[1]], c[f[2]], 0);
        addTriangle(scene, c[f[0]], c[f[2]], c[f[3]], 0);
    }
    addSquare(scene, 0.5f * side, outside ? 1.0f : 0.99f, !outside, 1);
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

// A lamp whose light all leaves the scene lights nothing, however bright (MultiUVTest's emissive
// cube): the sky is added; the same lamp inside the room keeps the scene to itself.
TEST(DefaultLighting, AnEmitterThatLightsNothingGetsTheSky) {
    EXPECT_EQ(emitterLanding(cubeWithLamp(0.5f, 40.0f)), 1.0);
    EXPECT_EQ(emitterLanding(cubeWithLamp(0.5f, 40.0f, true)), 0.0);
    Scene detail = cubeWithLamp(0.5f, 40.0f, true);
    ASSERT_GT(emitterShare(detail).share(), 0.2);  // by power alone it would light the scene
    std::string note;
    applyEnvironment(detail, {}, note);
    EXPECT_TRUE(detail.environment.present);
    EXPECT_NE(note.find("0 % of their light lands"), std::string::npos) << note;
    EXPECT_EQ(landedEmitterShare(detail).share(), 0.0);
}

// The landing fraction of a small lamp facing a square plate is the view factor from a point to
// a parallel coaxial square (four corner rectangles; Howell's catalogue, configuration B-3):
// 0.554 for a plate of half-size 1 at distance 1, 0.239 at distance 2.
TEST(DefaultLighting, LandingIsTheViewFactorToWhatTheEmitterFaces) {
    const auto cornerFactor = [](double a, double b) {
        const double sa = std::sqrt(1.0 + a * a), sb = std::sqrt(1.0 + b * b);
        return (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb)) / (2.0 * M_PI);
    };
    for (const float distance : {1.0f, 2.0f}) {
        Scene scene;
        Material grey, lamp;
        lamp.emissive = glm::vec3(1.0f);
        scene.materials = {grey, lamp};
        addSquare(scene, 1.0f, distance, true, 0);
        addSquare(scene, 0.005f, 0.0f, false, 1);
        const double expected = 4.0 * cornerFactor(1.0 / distance, 1.0 / distance);
        // 4096 rays: a standard deviation under 0.008.
        EXPECT_NEAR(emitterLanding(scene), expected, 0.03) << distance;
        EXPECT_NEAR(emitterLanding(scene, 65536), expected, 0.008) << distance;
        EXPECT_EQ(emitterLanding(scene), emitterLanding(scene));  // deterministic
    }
}

TEST(DefaultLighting, TheShippedScenesWithLampsKeepTheirOwnLight) {
    for (const char* name : {"cornell-box", "cornell-ceiling", "cornell-glass", "cubicles-1024", "door-slit",
                             "hall-moving", "rooms-10x10"}) {
        Scene scene = loadGltf(fs::path(VKPHOTON_SCENES) / (std::string(name) + ".gltf"));
        const double share = landedEmitterShare(scene).share();
        EXPECT_GT(share, 2.0 * kMinEmitterShare) << name;  // a margin: no scene near the threshold
        std::string note;
        applyEnvironment(scene, {}, note);
        EXPECT_FALSE(scene.environment.present) << name << ": " << note;
    }
}

}  // namespace
}  // namespace vkp
