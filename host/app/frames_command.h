// `vkphoton render --frames FIRST:LAST`: an animated glTF scene rendered frame by frame
// (docs/animation.md). The file is parsed once; each frame flattens the scene at its time,
// rebuilds the BVH, uploads it and renders with photon maps built through the sequence's
// FrameUpdate (animation/frame_update.h).
#pragma once

#include "app/commands.h"

namespace vkp {

// The output of frame `frame`: -o with its run(s) of '#' replaced (required), default
// out/SCENE-####.exr. Throws InputError for an -o without '#'.
std::filesystem::path framesOutputPattern(const RenderCommandOptions& options);

int runRenderFrames(const RenderCommandOptions& options, const IntegratorConfig& config);

}  // namespace vkp
