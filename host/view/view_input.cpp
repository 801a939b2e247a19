#include "view/view_input.h"

#include <algorithm>
#include <cctype>

namespace vkp {
namespace {

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

}  // namespace

std::optional<ViewKey> parseKeyName(std::string_view name) {
    const std::string key = lower(name);
    if (key == "i") return ViewKey::Integrator;
    if (key == "r") return ViewKey::Restart;
    if (key == "s") return ViewKey::Screenshot;
    if (key == "space") return ViewKey::PlayPause;
    if (key == "h") return ViewKey::Help;
    if (key == "q" || key == "escape" || key == "esc") return ViewKey::Quit;
    return std::nullopt;
}

std::optional<DragButton> parseDragButton(std::string_view name) {
    const std::string button = lower(name);
    if (button == "left") return DragButton::Left;
    if (button == "right") return DragButton::Right;
    if (button == "shift") return DragButton::ShiftLeft;
    return std::nullopt;
}

ViewAction dragAction(DragButton button, glm::vec2 from, glm::vec2 to) {
    ViewAction action;
    switch (button) {
    case DragButton::Left:
        action.kind = ViewAction::Kind::Orbit;
        action.a = (to - from) * kOrbitDegreesPerPixel;
        break;
    case DragButton::Right:
        action.kind = ViewAction::Kind::Pan;
        action.a = from;
        action.b = to;
        break;
    case DragButton::ShiftLeft:
        action.kind = ViewAction::Kind::MoveSelected;
        action.a = from;
        action.b = to;
        break;
    }
    return action;
}

std::string viewHelpText() {
    return "vkphoton view controls:\n"
           "  left drag         orbit about the look-at point\n"
           "  right drag        pan\n"
           "  wheel             dolly towards / away from the look-at point\n"
           "  click             select the node under the cursor (outlined)\n"
           "  Shift+left drag   move the selected node in the plane through its centre parallel to the image\n"
           "  I                 next integrator\n"
           "  R                 restart (photon maps traced in full)\n"
           "  S                 screenshot: out/SCENE-view-N.exr and .png\n"
           "  Space             play / pause the scene's animation\n"
           "  H                 this help\n"
           "  Q, Esc            quit\n";
}

}  // namespace vkp
