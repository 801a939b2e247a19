// What the viewer's input means, apart from where it comes from (GLFW's callbacks or an event
// script): the keys it knows and the mouse drags, as one list of actions the view loop applies.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace vkp {

enum class ViewKey {
    Integrator,  // I: the next integrator
    Restart,     // R: start accumulating afresh (photon maps retraced in full)
    Screenshot,  // S: write out/SCENE-view-N.exr and .png
    PlayPause,   // Space: play or pause the scene's glTF animation
    Help,        // H: print the controls
    Quit,        // Q or Escape
};

enum class DragButton { Left, Right, ShiftLeft };

// A script's key name (i, r, s, space, h, q, escape; case-insensitive), or nothing.
std::optional<ViewKey> parseKeyName(std::string_view name);
// A script's drag button name (left, right, shift), or nothing.
std::optional<DragButton> parseDragButton(std::string_view name);

// Orbit speed of a left drag and the dolly step of one wheel notch.
inline constexpr float kOrbitDegreesPerPixel = 0.3f;
inline constexpr float kDollyPerNotch = 0.9f;  // distance to the look-at point times this per notch towards it
// A press and release closer than this (pixels) is a click, not a drag.
inline constexpr float kClickSlopPixels = 3.0f;

struct ViewAction {
    enum class Kind { Orbit, Pan, Dolly, Select, MoveSelected, MoveNode, Key, Resize };
    Kind kind = Kind::Key;
    glm::vec2 a{0.0f};         // Orbit: degrees (x: about up, y: elevation); Pan/MoveSelected: from; Select: pixel;
                               // Resize: the new width and height in pixels
    glm::vec2 b{0.0f};         // Pan/MoveSelected: to
    float amount = 0.0f;       // Dolly: wheel notches (positive: towards the look-at point)
    std::string node;          // MoveNode
    glm::dvec3 delta{0.0};     // MoveNode: world units
    ViewKey key = ViewKey::Help;
};

// The action a drag from `from` to `to` with `button` makes (a left drag orbits by
// kOrbitDegreesPerPixel per pixel, right pans, Shift+left moves the selected node).
ViewAction dragAction(DragButton button, glm::vec2 from, glm::vec2 to);

// The controls, as H prints them.
std::string viewHelpText();

}  // namespace vkp
