// A small frame for tests: size x size pixels, spp samples, a seed; every other setting at
// FrameSettings' defaults. Tests change what they study on the result.
#pragma once

#include <cstdint>

#include "render/frame.h"

namespace vkp::test {

inline FrameSettings smallFrame(uint32_t size, uint32_t spp, uint32_t seed = 0) {
    FrameSettings s;
    s.width = size;
    s.height = size;
    s.samplesPerPixel = spp;
    s.seed = seed;
    return s;
}

}  // namespace vkp::test
