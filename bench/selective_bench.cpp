// Image side of the selective photon update benchmark (docs/benchmarks.md "Selective photon
// update"): the relative MSE of rendered frames against a reference EXR of the same frame, and
// the temporal flicker between two consecutive frames in the regions the motion leaves alone.
// The frames come from `vkphoton render --frames` with --photon-update selective and full; their
// per-frame paths traced and seconds are in the --stats-json output.
//   selective_bench REFERENCE.exr FRAME.exr...
//   selective_bench --flicker REF_A.exr REF_B.exr A.exr B.exr
//       relMSE of B against A over the pixels where the references of the two frames (converged,
//       same seed) differ by at most 2 % (the static regions), and the share of such pixels.
//   selective_bench --changed REF_A REF_B FRAME...
//       relMSE of each FRAME against REF_B over the other pixels (those the motion from frame A to
//       frame B changes: the moving object, its shadow and caustic), and their share.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "image/exr.h"
#include "image/metrics.h"

namespace {

// The pixel is static: the two references differ by at most 2 % in every channel.
bool staticPixel(const vkp::ImageRgb& ra, const vkp::ImageRgb& rb, size_t p) {
    bool same = true;
    for (int c = 0; c < 3; ++c) {
        const double x = ra.pixels[3 * p + c], y = rb.pixels[3 * p + c];
        same = same && std::abs(x - y) <= 0.02 * std::max(0.5 * (x + y), 1e-3);
    }
    return same;
}

int changed(int count, char** paths) {
    const vkp::ImageRgb ra = vkp::readExr(paths[0]), rb = vkp::readExr(paths[1]);
    const size_t pixels = ra.pixels.size() / 3;
    for (int i = 2; i < count; ++i) {
        const vkp::ImageRgb image = vkp::readExr(paths[i]);
        if (rb.pixels.size() != ra.pixels.size() || image.pixels.size() != ra.pixels.size()) {
            std::fprintf(stderr, "error: the images differ in size\n");
            return 2;
        }
        double sum = 0.0;
        size_t moved = 0;
        for (size_t p = 0; p < pixels; ++p) {
            if (staticPixel(ra, rb, p)) continue;
            ++moved;
            for (int c = 0; c < 3; ++c) {  // relMSE as image/metrics.h: (a - b)^2 / (b^2 + 0.01)
                const double d = image.pixels[3 * p + c] - rb.pixels[3 * p + c];
                const double r = rb.pixels[3 * p + c];
                sum += d * d / (r * r + 0.01);
            }
        }
        fmt::print("{}\tchanged-pixel relMSE {:.5f}\tchanged pixels {:.1f} %\n", paths[i], moved ? sum / (3.0 * moved) : 0.0,
                   100.0 * double(moved) / double(pixels));
    }
    return 0;
}

int flicker(const char* refA, const char* refB, const char* a, const char* b) {
    const vkp::ImageRgb ra = vkp::readExr(refA), rb = vkp::readExr(refB), ia = vkp::readExr(a), ib = vkp::readExr(b);
    if (ra.pixels.size() != rb.pixels.size() || ia.pixels.size() != ra.pixels.size() || ib.pixels.size() != ra.pixels.size()) {
        std::fprintf(stderr, "error: the four images differ in size\n");
        return 2;
    }
    double sum = 0.0;
    size_t still = 0;
    const size_t pixels = ra.pixels.size() / 3;
    for (size_t p = 0; p < pixels; ++p) {
        if (!staticPixel(ra, rb, p)) continue;
        ++still;
        for (int c = 0; c < 3; ++c) {  // relMSE as image/metrics.h: (a - b)^2 / (b^2 + 0.01)
            const double d = ia.pixels[3 * p + c] - ib.pixels[3 * p + c];
            const double r = ia.pixels[3 * p + c];
            sum += d * d / (r * r + 0.01);
        }
    }
    fmt::print("{}\t{}\tflicker relMSE {:.5f}\tstatic pixels {:.1f} %\n", a, b, still ? sum / (3.0 * still) : 0.0,
               100.0 * double(still) / double(pixels));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3 || (std::strcmp(argv[1], "--flicker") == 0 && argc != 6) ||
        (std::strcmp(argv[1], "--changed") == 0 && argc < 5)) {
        std::fprintf(stderr, "usage: selective_bench REFERENCE.exr FRAME.exr...\n"
                             "       selective_bench --flicker REF_A.exr REF_B.exr A.exr B.exr\n"
                             "       selective_bench --changed REF_A.exr REF_B.exr FRAME.exr...\n");
        return 2;
    }
    try {
        if (std::strcmp(argv[1], "--flicker") == 0) return flicker(argv[2], argv[3], argv[4], argv[5]);
        if (std::strcmp(argv[1], "--changed") == 0) return changed(argc - 2, argv + 2);
        const vkp::ImageRgb reference = vkp::readExr(argv[1]);
        for (int i = 2; i < argc; ++i)
            fmt::print("{}\trelMSE {:.5f}\n", argv[i], vkp::relativeMse(vkp::readExr(argv[i]), reference));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
