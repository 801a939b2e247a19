// Parts of one render (--tile, --crop) and `vkphoton merge`, which joins them into the full
// image (docs/distributed-rendering.md). A part's EXR header says where it belongs: the full
// frame's size, its window, and a fingerprint of every setting that shapes its pixels; merge
// refuses parts that disagree, overlap or leave pixels uncovered (exit 2).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/exr.h"
#include "render/frame.h"

namespace vkp {

class Stats;

// The EXR header attributes of a part rendered with `frame.crop` (none without a window):
// vkphoton/fullWidth, vkphoton/fullHeight, vkphoton/crop ("x0,y0,x1,y1") and
// vkphoton/partSettings (the render's settings.* stats but the time limit, as JSON).
ExrAttributes partAttributes(const FrameSettings& frame, const Stats& stats);

struct MergeCommandOptions {
    std::vector<std::filesystem::path> parts;  // EXRs written by render --tile / --crop
    std::filesystem::path output;              // .exr; a PNG is written beside it
    bool quiet = false;
};

// Joins the parts; InputError (exit 2) naming the file for a part that is missing its header,
// disagrees with the first part, overlaps another or leaves pixels of the frame uncovered.
int runMerge(const MergeCommandOptions& options);

}  // namespace vkp
