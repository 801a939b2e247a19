#include "render/sample_loop.h"

#include <algorithm>

#include "util/stopwatch.h"

namespace vkp {
namespace {

// Each submission aims at this much device time, so progress, the time limit and Ctrl-C are
// honoured promptly while few submissions keep the per-dispatch overhead small.
constexpr double kTargetBatchSeconds = 0.3;

}  // namespace

SampleLoopResult runSampleLoop(uint32_t samples, const RenderControl& control, uint32_t maxBatch,
                               const ProgressCallback& progress,
                               const std::function<void(uint32_t firstSample, uint32_t count)>& runBatch) {
    SampleLoopResult result;
    const auto start = Clock::now();
    uint32_t batch = 1;
    while (result.samplesDone < samples) {
        if (result.samplesDone > 0)
            if (std::string reason = control.stopReason(); !reason.empty()) {
                result.stopReason = std::move(reason);
                break;
            }
        const uint32_t count = std::min({batch, maxBatch, samples - result.samplesDone});
        const auto batchStart = Clock::now();
        runBatch(result.samplesDone, count);
        const double batchSeconds = secondsSince(batchStart);
        result.samplesDone += count;
        // Grow or shrink the next batch towards the target time per submission.
        const double perSample = batchSeconds / count;
        double next = perSample > 0.0 ? kTargetBatchSeconds / perSample : 2.0 * batch;
        if (control.deadline) next = std::min(next, std::max(1.0, control.secondsLeft() / perSample));
        batch = static_cast<uint32_t>(std::clamp(next, 1.0, 4096.0));
        if (progress) progress({result.samplesDone, samples, secondsSince(start)});
    }
    result.seconds = secondsSince(start);
    return result;
}

}  // namespace vkp
