// `vkphoton compare A.exr B.exr`: are two EXRs' pixels the same, bit for bit? The way to check
// "the same seed gives the same image" (docs/architecture.md, "Determinism"): the files' bytes
// cannot tell, because the header holds the run's timings, and a timing one digit longer moves
// every scan-line block and so changes the offset table that follows the header even when every
// pixel is the same.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vkp {

struct ExrComparison {
    uint32_t width = 0, height = 0;                  // A's size
    bool sameSize = false;
    std::vector<std::string> channels;               // the channels both files have (all compared)
    std::vector<std::string> channelsInOneOnly;      // each marked "A: name" or "B: name"
    uint64_t values = 0;                             // values compared (pixels x common channels)
    uint64_t differingValues = 0, differingPixels = 0;
    std::string firstDifference;                     // "(x, y) channel: a vs b" in scan-line order
    double largestDifference = 0.0;                  // max |a - b| over differing finite pairs
    std::vector<std::string> differingAttributes;    // string header attributes that differ or are in one file only

    bool pixelsIdentical() const { return sameSize && channelsInOneOnly.empty() && differingValues == 0; }
};

// Compares every channel of two EXRs (R, G, B and any AOV channels) value by value, as bit
// patterns (so -0 and +0 differ, and a NaN equals only the same NaN). InputError naming the file
// when one cannot be read or is not an RGB image.
ExrComparison compareExrs(const std::filesystem::path& a, const std::filesystem::path& b);

struct CompareCommandOptions {
    std::filesystem::path a, b;
    bool quiet = false;  // no output, only the exit code
};

// Prints the comparison; exit 0 when the pixels are identical, kExitImagesDiffer (3) when they
// are not, 2 when a file cannot be read.
int runCompare(const CompareCommandOptions& options);

}  // namespace vkp
