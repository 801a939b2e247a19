// Sky boxes (lights/backdrop.h, docs/environment.md "Sky boxes"): an inward-facing single-sided
// box around the whole scene, which hides the environment from it, is a backdrop; a box that is
// double-sided, faces out, glows, lets the sky in through an open side or does not hold the
// scene is not. The default lighting rule looks for them only where the environment is the light.
#include <string>

#include <gtest/gtest.h>

#include "lights/backdrop.h"
#include "lights/default_lighting.h"
#include "support/sky_box_scenes.h"
#include "support/test_scenes.h"

namespace vkp {
namespace {

const BackdropCandidate* candidate(const std::vector<BackdropCandidate>& candidates, int node) {
    for (const BackdropCandidate& c : candidates)
        if (c.node == node) return &c;
    return nullptr;
}

TEST(SkyBox, AnInwardBoxAroundTheSceneIsABackdrop) {
    const Scene scene = test::skyBoxScene();
    const auto candidates = backdropCandidates(scene);
    const BackdropCandidate* box = candidate(candidates, 0);
    ASSERT_NE(box, nullptr);
    EXPECT_DOUBLE_EQ(box->inwardArea, 1.0);
    EXPECT_TRUE(box->enclosesOthers);
    // Every ray leaving the cube ends on the box (the cube's faces look away from each other).
    EXPECT_DOUBLE_EQ(box->raysOnIt, 1.0);
    EXPECT_DOUBLE_EQ(box->raysEscaping, 0.0);
    EXPECT_TRUE(box->backdrop);
    // The cube faces out: not a shell.
    const BackdropCandidate* cube = candidate(candidates, 1);
    ASSERT_NE(cube, nullptr);
    EXPECT_DOUBLE_EQ(cube->inwardArea, 0.0);
    EXPECT_FALSE(cube->backdrop);
    EXPECT_EQ(findBackdrops(scene), std::vector<int>{0});
}

// `view` draws every node as an instance: the box is found there too.
TEST(SkyBox, AnInstancedSkyBox) {
    const Scene scene = test::skyBoxScene({.instanced = true});
    ASSERT_EQ(scene.instances.size(), 1u);
    const auto candidates = backdropCandidates(scene);
    const BackdropCandidate* box = candidate(candidates, 0);
    ASSERT_NE(box, nullptr);
    EXPECT_DOUBLE_EQ(box->inwardArea, 1.0);
    EXPECT_DOUBLE_EQ(box->raysOnIt, 1.0);
    EXPECT_EQ(findBackdrops(scene), std::vector<int>{0});
    EXPECT_TRUE(findBackdrops(test::skyBoxScene({.doubleSided = true, .instanced = true})).empty());
}

TEST(SkyBox, BoxesThatAreNotSkyBoxes) {
    for (const auto& [name, options] :
         {std::pair{"double-sided", test::SkyBoxOptions{.doubleSided = true}},
          std::pair{"facing out", test::SkyBoxOptions{.outward = true}},
          std::pair{"emissive", test::SkyBoxOptions{.emissive = true}},
          std::pair{"open top", test::SkyBoxOptions{.openTop = true}},
          std::pair{"cube outside", test::SkyBoxOptions{.cubeOutside = true}},
          std::pair{"alone", test::SkyBoxOptions{.withBox = false}}}) {
        const Scene scene = test::skyBoxScene(options);
        EXPECT_TRUE(findBackdrops(scene).empty()) << name;
    }
    // The open top lets a sixth of the cube's light out (its top face's rays all leave, the
    // side faces' upper halves in part): the sky reaches the scene without help.
    const auto open = backdropCandidates(test::skyBoxScene({.openTop = true}));
    ASSERT_NE(candidate(open, 0), nullptr);
    EXPECT_GT(candidate(open, 0)->raysEscaping, 0.15);
    EXPECT_TRUE(candidate(open, 0)->enclosesOthers);
    const auto outside = backdropCandidates(test::skyBoxScene({.cubeOutside = true}));
    ASSERT_NE(candidate(outside, 0), nullptr);
    EXPECT_FALSE(candidate(outside, 0)->enclosesOthers);
}

TEST(SkyBox, OnlyWhereTheEnvironmentIsTheLight) {
    std::string note;
    Scene unlit = test::skyBoxScene();
    applyEnvironment(unlit, EnvironmentSettings{}, note);
    ASSERT_TRUE(unlit.environment.present);
    EXPECT_EQ(unlit.backdropNodes, std::vector<int>{0});
    EXPECT_NE(note.find("nodes[0] encloses the scene"), std::string::npos) << note;

    // --env given: the same.
    Scene sky = test::skyBoxScene();
    EnvironmentSettings two;
    two.value = "2";
    note.clear();
    applyEnvironment(sky, two, note);
    EXPECT_EQ(sky.backdropNodes, std::vector<int>{0});

    // A punctual light inside: a lit room, whose walls stay walls.
    Scene lit = test::skyBoxScene();
    test::addPointLight(lit, glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(10.0f));
    note.clear();
    applyEnvironment(lit, EnvironmentSettings{}, note);
    EXPECT_FALSE(lit.environment.present);
    EXPECT_TRUE(lit.backdropNodes.empty());
    note.clear();
    applyEnvironment(lit, two, note);  // and with --env: the light is the file's
    EXPECT_TRUE(lit.environment.present);
    EXPECT_TRUE(lit.backdropNodes.empty());
}

}  // namespace
}  // namespace vkp
