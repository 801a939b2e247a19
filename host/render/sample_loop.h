// The progressive sample loop of the driver: batches of samples per submission, sized towards a
// target time so that progress, the time limit and Ctrl-C are honoured promptly.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "render/render_control.h"

namespace vkp {

struct SampleLoopResult {
    uint32_t samplesDone = 0;
    std::string stopReason = "complete";  // "complete", "time limit", "interrupted"
    double seconds = 0.0;
};

// Calls runBatch(firstSample, count) with count <= maxBatch until `samples` samples are done or
// `control` says stop. The first sample is always rendered, so an image stopped before the
// loop (during the photon passes, say) still has one sample in every pixel.
SampleLoopResult runSampleLoop(uint32_t samples, const RenderControl& control, uint32_t maxBatch,
                               const ProgressCallback& progress,
                               const std::function<void(uint32_t firstSample, uint32_t count)>& runBatch);

}  // namespace vkp
