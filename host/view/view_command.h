// `vkphoton view SCENE [render options]` (docs/viewer.md): an interactive window that shows the
// image as it refines, lets the user orbit, pan, dolly, select and move nodes, with the photon
// maps updated selectively after a move; `--events FILE` replays a script, `--stats-json` reports
// the times to the first images.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.h"

namespace vkp {

struct ViewCommandOptions {
    // The render options that apply: scene, frame (size, --spp where accumulation stops, seed,
    // camera, --direct), display (the PNG of screenshots and the window), environment, device,
    // --stats-json, --photon-budget, --photon-groups, --quiet.
    RenderCommandOptions render;
    std::filesystem::path events;  // --events: the script; empty: none
    bool preview = true;           // --no-preview: no path-traced sample before a preparation
    bool headless = false;         // --headless: no window (needs --events); images go to an offscreen image
    bool sampleParts = true;       // --no-sample-parts: whole samples only
};

// `integrators`: the kinds I cycles through (name, config with its options parsed), starting at
// `first`. Throws InputError for bad input (exit 2), RuntimeError for failures (exit 1).
int runView(const ViewCommandOptions& options,
            const std::vector<std::pair<std::string, const IntegratorConfig*>>& integrators, size_t first);

}  // namespace vkp
