// Wall-clock timing for statistics, progress and benchmarks, and the process's CPU time (every
// thread's, lavapipe's workers included): on a machine shared with other jobs, work per CPU second
// varies less than work per wall-clock second.
#pragma once

#include <chrono>
#include <ctime>

namespace vkp {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU seconds this process has used so far, all threads together.
inline double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace vkp
