// Image side of the selective photon update benchmark (docs/benchmarks.md "Selective photon
// update"): the relative MSE of each rendered frame against a reference EXR of the same frame.
// The frames come from `vkphoton render --frames` with --photon-update selective and full; their
// per-frame paths traced and seconds are in the --stats-json output.
//   selective_bench REFERENCE.exr FRAME.exr...
#include <cstdio>

#include <fmt/format.h>

#include "image/exr.h"
#include "image/metrics.h"

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: selective_bench REFERENCE.exr FRAME.exr...\n");
        return 2;
    }
    try {
        const vkp::ImageRgb reference = vkp::readExr(argv[1]);
        for (int i = 2; i < argc; ++i)
            fmt::print("{}\trelMSE {:.5f}\n", argv[i], vkp::relativeMse(vkp::readExr(argv[i]), reference));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
