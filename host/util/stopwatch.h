// Wall-clock timing for statistics, progress and benchmarks.
#pragma once

#include <chrono>

namespace vkp {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace vkp
