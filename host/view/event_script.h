// `vkphoton view --events FILE` (docs/viewer.md): a script of viewer events, one command a line,
// each run after the previous one has finished. Parsing needs no window or device, so bad
// scripts are refused (exit 2, naming FILE:LINE) before anything opens.
//
//   samples N                 wait until the image holds N samples per pixel since the last change
//   seconds S                 wait S seconds
//   screenshot PATH.exr|.png  write the image as `render` does (EXR and the PNG beside it)
//   move NODE DX DY DZ        translate the glTF node named NODE by (DX, DY, DZ) world units
//   orbit DX_DEG DY_DEG       orbit the camera about its look-at point
//   click X Y                 select the node under window pixel (X, Y)
//   drag X0 Y0 X1 Y1 [BUTTON] drag from (X0, Y0) to (X1, Y1): left (orbit, the default), right
//                             (pan) or shift (Shift+left: move the selected node)
//   key NAME                  press a key: i, r, s, space, h, q, escape (view_input.h)
//   resize W H                resize the window (the image) to W x H pixels
//   quit                      close the window
//
// Blank lines and lines starting with '#' are skipped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "view/view_input.h"

namespace vkp {

enum class ScriptCommand { Samples, Seconds, Screenshot, Move, Orbit, Click, Drag, Key, Resize, Quit };

struct ScriptEvent {
    ScriptCommand command = ScriptCommand::Quit;
    std::string where;               // "FILE:LINE", for messages
    uint32_t samples = 0;            // samples
    double seconds = 0.0;            // seconds
    std::filesystem::path path;      // screenshot
    std::string node;                // move
    glm::dvec3 delta{0.0};           // move (world units)
    glm::vec2 from{0.0f};            // click (the point), drag, orbit (degrees in from), resize (the size)
    glm::vec2 to{0.0f};              // drag
    DragButton button = DragButton::Left;  // drag
    ViewKey key = ViewKey::Help;     // key
};

// Parses a script; `source` names it in messages. Throws InputError "SOURCE:LINE: ..." for an
// unknown command, a wrong argument count, a number that is not one or out of range, a
// screenshot path not ending in .exr or .png, an unknown key or button.
std::vector<ScriptEvent> parseEventScript(std::string_view text, const std::string& source);
// Reads and parses FILE (InputError when it cannot be read).
std::vector<ScriptEvent> readEventScript(const std::filesystem::path& file);

}  // namespace vkp
