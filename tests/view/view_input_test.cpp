// `vkphoton view`'s input handling without a window: the event script parser, the key and button
// names, the drag actions and the camera controller (docs/viewer.md).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "util/errors.h"
#include "view/camera_controller.h"
#include "view/event_script.h"
#include "view/script_player.h"
#include "view/view_input.h"

namespace vkp {
namespace {

std::string errorOf(const std::string& script) {
    try {
        parseEventScript(script, "s.txt");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(ViewEventScript, ParsesEveryCommand) {
    const auto events = parseEventScript(
        "# a comment\n"
        "samples 16\n"
        "\n"
        "seconds 0.5\n"
        "screenshot out/a.exr\n"
        "move glass-sphere 0.25 -1 2e-1\n"
        "orbit 30 -10\n"
        "click 12 40\n"
        "drag 1 2 30 40\n"
        "drag 1 2 30 40 shift\r\n"
        "key SPACE\n"
        "resize 320 200\n"
        "quit",
        "s.txt");
    ASSERT_EQ(events.size(), 11u);
    EXPECT_EQ(events[0].command, ScriptCommand::Samples);
    EXPECT_EQ(events[0].samples, 16u);
    EXPECT_EQ(events[0].where, "s.txt:2");
    EXPECT_EQ(events[1].command, ScriptCommand::Seconds);
    EXPECT_DOUBLE_EQ(events[1].seconds, 0.5);
    EXPECT_EQ(events[1].where, "s.txt:4");
    EXPECT_EQ(events[2].path, "out/a.exr");
    EXPECT_EQ(events[3].node, "glass-sphere");
    EXPECT_DOUBLE_EQ(events[3].delta.x, 0.25);
    EXPECT_DOUBLE_EQ(events[3].delta.y, -1.0);
    EXPECT_DOUBLE_EQ(events[3].delta.z, 0.2);
    EXPECT_EQ(events[4].command, ScriptCommand::Orbit);
    EXPECT_FLOAT_EQ(events[4].from.x, 30.0f);
    EXPECT_FLOAT_EQ(events[4].from.y, -10.0f);
    EXPECT_EQ(events[5].command, ScriptCommand::Click);
    EXPECT_EQ(events[6].button, DragButton::Left);
    EXPECT_EQ(events[7].button, DragButton::ShiftLeft);
    EXPECT_FLOAT_EQ(events[7].to.y, 40.0f);
    EXPECT_EQ(events[8].key, ViewKey::PlayPause);
    EXPECT_EQ(events[9].command, ScriptCommand::Resize);
    EXPECT_FLOAT_EQ(events[9].from.x, 320.0f);
    EXPECT_FLOAT_EQ(events[9].from.y, 200.0f);
    EXPECT_EQ(events[10].command, ScriptCommand::Quit);
    EXPECT_EQ(events[10].where, "s.txt:13");
}

TEST(ViewEventScript, BadLinesAreRefusedNamingTheLine) {
    EXPECT_NE(errorOf("samples 4\nfly 1 2\n").find("s.txt:2: unknown command 'fly'"), std::string::npos)
        << errorOf("samples 4\nfly 1 2\n");
    EXPECT_NE(errorOf("samples 0").find("s.txt:1"), std::string::npos);
    EXPECT_NE(errorOf("samples 2.5").find("s.txt:1"), std::string::npos);
    EXPECT_NE(errorOf("seconds -1").find("s.txt:1"), std::string::npos);
    EXPECT_NE(errorOf("seconds nan").find("not a finite number"), std::string::npos);
    EXPECT_NE(errorOf("\n\nscreenshot a.jpg").find("s.txt:3"), std::string::npos);
    EXPECT_NE(errorOf("move sphere 1 2").find("move NODE DX DY DZ"), std::string::npos);
    EXPECT_NE(errorOf("move sphere 1 2 x").find("'x' is not a finite number"), std::string::npos);
    EXPECT_NE(errorOf("orbit 1").find("s.txt:1"), std::string::npos);
    EXPECT_NE(errorOf("drag 1 2 3 4 middle").find("unknown button 'middle'"), std::string::npos);
    EXPECT_NE(errorOf("key F5").find("unknown key 'F5'"), std::string::npos);
    EXPECT_NE(errorOf("quit now").find("s.txt:1"), std::string::npos);
    EXPECT_NE(errorOf("resize 64").find("resize W H"), std::string::npos);
    EXPECT_NE(errorOf("resize 0 64").find("from 1 to 16384"), std::string::npos);
    EXPECT_NE(errorOf("resize 64 20000").find("from 1 to 16384"), std::string::npos);
    EXPECT_NE(errorOf("resize 64.5 64").find("whole number"), std::string::npos);
    EXPECT_EQ(errorOf("# only a comment\n\n"), "no error");
}

TEST(ViewInput, KeyAndButtonNames) {
    EXPECT_EQ(parseKeyName("i"), ViewKey::Integrator);
    EXPECT_EQ(parseKeyName("R"), ViewKey::Restart);
    EXPECT_EQ(parseKeyName("s"), ViewKey::Screenshot);
    EXPECT_EQ(parseKeyName("space"), ViewKey::PlayPause);
    EXPECT_EQ(parseKeyName("h"), ViewKey::Help);
    EXPECT_EQ(parseKeyName("q"), ViewKey::Quit);
    EXPECT_EQ(parseKeyName("Escape"), ViewKey::Quit);
    EXPECT_FALSE(parseKeyName("x"));
    EXPECT_EQ(parseDragButton("right"), DragButton::Right);
    EXPECT_FALSE(parseDragButton("middle"));
}

TEST(ViewInput, DragsMapToOrbitPanAndMove) {
    const ViewAction orbit = dragAction(DragButton::Left, {10.0f, 10.0f}, {20.0f, 5.0f});
    EXPECT_EQ(orbit.kind, ViewAction::Kind::Orbit);
    EXPECT_FLOAT_EQ(orbit.a.x, 10.0f * kOrbitDegreesPerPixel);
    EXPECT_FLOAT_EQ(orbit.a.y, -5.0f * kOrbitDegreesPerPixel);
    EXPECT_EQ(dragAction(DragButton::Right, {0, 0}, {1, 1}).kind, ViewAction::Kind::Pan);
    const ViewAction move = dragAction(DragButton::ShiftLeft, {1, 2}, {3, 4});
    EXPECT_EQ(move.kind, ViewAction::Kind::MoveSelected);
    EXPECT_EQ(move.b, glm::vec2(3, 4));
}

Camera testCamera() {
    Camera c;
    c.position = {0.0f, 1.0f, 4.0f};
    c.forward = {0.0f, 0.0f, -1.0f};
    c.up = {0.0f, 1.0f, 0.0f};
    c.yfov = glm::radians(40.0f);
    return c;
}

// Where a world point lands in the image of the controller's camera (pixels, y down).
glm::vec2 project(const CameraController& cam, glm::vec3 p, float yfov, uint32_t size) {
    const glm::vec3 f = glm::normalize(cam.target() - cam.position());
    const glm::vec3 r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    const glm::vec3 u = glm::cross(r, f);
    const glm::vec3 d = p - cam.position();
    const float depth = glm::dot(d, f);
    const float scale = float(size) / (2.0f * std::tan(0.5f * yfov) * depth);
    return {0.5f * size + glm::dot(d, r) * scale, 0.5f * size - glm::dot(d, u) * scale};
}

TEST(ViewCamera, StartsUnchangedAndLooksAtThePivotDepth) {
    const CameraController cam(testCamera(), {0.5f, 0.0f, 0.0f});
    EXPECT_FALSE(cam.changed());
    ViewOverride base;
    base.fovDegrees = 50.0f;
    EXPECT_EQ(cam.view(base).fovDegrees, 50.0f);  // untouched: the user's own override
    EXPECT_FALSE(cam.view(base).lookFrom);
    EXPECT_NEAR(glm::length(cam.target() - glm::vec3(0.0f, 1.0f, 0.0f)), 0.0f, 1e-5f);
}

TEST(ViewCamera, OrbitKeepsTheDistanceAndTurnsAboutUp) {
    CameraController cam(testCamera(), {0.0f, 1.0f, 0.0f});
    cam.orbit(90.0f, 0.0f);
    EXPECT_TRUE(cam.changed());
    EXPECT_NEAR(glm::length(cam.position() - cam.target()), 4.0f, 1e-4f);
    EXPECT_NEAR(cam.position().x, -4.0f, 1e-4f);  // a quarter turn: from +Z to -X
    EXPECT_NEAR(cam.position().y, 1.0f, 1e-4f);
    cam.orbit(0.0f, 200.0f);  // elevation is clamped short of the pole
    EXPECT_NEAR(glm::degrees(std::asin((cam.position().y - 1.0f) / 4.0f)), 85.0f, 1e-3f);
    const ViewOverride v = cam.view({});
    ASSERT_TRUE(v.lookFrom && v.lookAt && v.fovDegrees);
    EXPECT_NEAR(*v.fovDegrees, 40.0f, 1e-4f);
}

TEST(ViewCamera, DollyAndPan) {
    CameraController cam(testCamera(), {0.0f, 1.0f, 0.0f});
    cam.dolly(1.0f);
    EXPECT_NEAR(glm::length(cam.position() - cam.target()), 4.0f * kDollyPerNotch, 1e-4f);
    cam.dolly(-2.0f);
    EXPECT_NEAR(glm::length(cam.position() - cam.target()), 4.0f / kDollyPerNotch, 1e-4f);
    // Panning drags the scene with the cursor: the look-at point's pixel moves by the drag.
    CameraController pan(testCamera(), {0.0f, 1.0f, 0.0f});
    const glm::vec3 point(0.0f, 1.0f, 0.0f);
    pan.pan({100.0f, 100.0f}, {130.0f, 90.0f}, 200);
    const glm::vec2 at = project(pan, point, glm::radians(40.0f), 200);
    EXPECT_NEAR(at.x, 130.0f, 1e-3f);
    EXPECT_NEAR(at.y, 90.0f, 1e-3f);
}

TEST(ViewCamera, ImagePlaneDeltaFollowsTheCursor) {
    const CameraController cam(testCamera(), {0.0f, 1.0f, 0.0f});
    const glm::vec3 centre(0.3f, 0.8f, -1.0f);
    const glm::vec2 from = project(cam, centre, glm::radians(40.0f), 256);
    const glm::vec3 delta = cam.imagePlaneDelta(centre, from, from + glm::vec2(25.0f, -40.0f), 256);
    EXPECT_NEAR(delta.z, 0.0f, 1e-5f);  // parallel to the image
    const glm::vec2 to = project(cam, centre + delta, glm::radians(40.0f), 256);
    EXPECT_NEAR(to.x - from.x, 25.0f, 1e-3f);
    EXPECT_NEAR(to.y - from.y, -40.0f, 1e-3f);
}

// The script's waits, without a window: the player is driven with made-up view states.
TEST(ViewScriptPlayer, CommandsWaitForWhatTheyNeed) {
    ScriptPlayer player(parseEventScript("screenshot a.png\nsamples 4\nmove ball 1 0 0\norbit 5 0\nseconds 2\n"
                                         "samples 64\nscreenshot b.exr\nquit\nkey h\n",
                                         "s.txt"));
    std::vector<std::string> shots;
    const auto shoot = [&](const ScriptEvent& e) { shots.push_back(e.path.string()); };
    bool quit = false;
    ScriptState state;
    state.targetSamples = 16;
    // Nothing on screen yet: the screenshot waits.
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    EXPECT_TRUE(shots.empty());
    // An image of 2 spp: the screenshot is taken, `samples 4` waits.
    state.shownSamples = 2;
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    EXPECT_EQ(shots, std::vector<std::string>{"a.png"});
    // 4 spp but a refresh round is due: still waiting; then the move comes back alone.
    state.shownSamples = 4;
    state.refreshDue = true;
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    state.refreshDue = false;
    std::vector<ViewAction> actions = player.advance(state, shoot, quit);
    ASSERT_EQ(actions.size(), 1u);
    EXPECT_EQ(actions[0].kind, ViewAction::Kind::MoveNode);
    EXPECT_EQ(actions[0].node, "ball");
    // The orbit waits until the move has been shown.
    state.changeShown = false;
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    state.changeShown = true;
    actions = player.advance(state, shoot, quit);
    ASSERT_EQ(actions.size(), 1u);
    EXPECT_EQ(actions[0].kind, ViewAction::Kind::Orbit);
    // `seconds 2` counts from when it is reached.
    const auto t0 = Clock::now();
    state.now = t0;
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    EXPECT_TRUE(player.waitingForTime());
    state.now = t0 + std::chrono::milliseconds(1900);
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    // Past it, `samples 64` is capped at --spp 16: 16 shown is enough; the screenshot and quit
    // follow, and nothing after quit runs.
    state.now = t0 + std::chrono::milliseconds(2100);
    state.shownSamples = 15;
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    EXPECT_FALSE(quit);
    state.shownSamples = 16;
    EXPECT_TRUE(player.advance(state, shoot, quit).empty());
    EXPECT_TRUE(quit);
    EXPECT_EQ(shots, (std::vector<std::string>{"a.png", "b.exr"}));
    EXPECT_FALSE(player.finished());  // `key h` after quit never ran
}

}  // namespace
}  // namespace vkp
