// The pieces of `render --frames` that are not the render itself (docs/animation.md): the frame
// range, frame times and output names with the frame number in place of a run of '#'.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace vkp {

struct FrameRange {
    uint32_t first = 0;
    uint32_t last = 0;  // inclusive
    uint32_t count() const { return last - first + 1; }
};

// "FIRST:LAST" (non-negative integers, FIRST <= LAST, at most kMaxFrames frames) or a single
// "N"; throws InputError naming --frames otherwise.
inline constexpr uint32_t kMaxFrames = 100000;
FrameRange parseFrameRange(const std::string& text);

// The time of frame `frame` at `fps` frames per second: frame / fps seconds (frame 0 at t = 0).
double frameTime(uint32_t frame, double fps);

// Whether the path's file name holds a run of '#'.
bool hasFramePattern(const std::filesystem::path& pattern);

// Every run of '#' in the file name replaced by `frame`, zero-padded to the run's length
// (wider when the number needs more digits): "out/f-####.exr", 7 -> "out/f-0007.exr".
std::filesystem::path frameOutputPath(const std::filesystem::path& pattern, uint32_t frame);

}  // namespace vkp
