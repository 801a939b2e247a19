// When a render should stop early: Ctrl-C/SIGTERM/SIGHUP (the stop flag) or --time-limit (the
// deadline). The driver fills one per render (Frame::control); every long phase checks it
// between bounded chunks of work: photon paths (photon/photon_map), the guide, the sample loop.
// A phase that stops keeps what it finished; the render still adds one sample, marked partial.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "util/stopwatch.h"

namespace vkp {

// How far a render has come, for progress output.
struct RenderProgress {
    uint32_t samplesDone = 0;
    uint32_t samplesTotal = 0;
    double elapsedSeconds = 0.0;
};

using ProgressCallback = std::function<void(const RenderProgress&)>;

struct RenderControl {
    const std::atomic<bool>* stop = nullptr;  // set by a signal handler
    std::optional<Clock::time_point> deadline;

    // "interrupted", "time limit", or "" while the render may go on.
    std::string stopReason() const {
        if (stop && stop->load()) return "interrupted";
        if (deadline && Clock::now() >= *deadline) return "time limit";
        return {};
    }
    bool shouldStop() const { return !stopReason().empty(); }
    // Seconds left before the deadline (infinity without one).
    double secondsLeft() const;
};

}  // namespace vkp
