#include "render/sample_loop.h"

#include <algorithm>

#include "util/stopwatch.h"

namespace vkp {
namespace {

// Each submission aims at this much device time, so progress, the time limit and Ctrl-C are
// honoured promptly while few submissions keep the per-dispatch overhead small.
constexpr double kTargetBatchSeconds = 0.3;

}  // namespace

SampleLoopResult runSampleLoop(const RenderSettings& settings, uint32_t maxBatch, const ProgressCallback& progress,
                               const std::atomic<bool>* stop,
                               const std::function<void(uint32_t firstSample, uint32_t count)>& runBatch) {
    SampleLoopResult result;
    const auto start = Clock::now();
    uint32_t batch = 1;
    while (result.samplesDone < settings.samplesPerPixel) {
        if (stop && stop->load()) { result.stopReason = "interrupted"; break; }
        if (settings.timeLimitSeconds > 0.0 && secondsSince(start) >= settings.timeLimitSeconds) {
            result.stopReason = "time limit";
            break;
        }
        const uint32_t count = std::min({batch, maxBatch, settings.samplesPerPixel - result.samplesDone});
        const auto batchStart = Clock::now();
        runBatch(result.samplesDone, count);
        const double batchSeconds = secondsSince(batchStart);
        result.samplesDone += count;
        // Grow or shrink the next batch towards the target time per submission.
        const double perSample = batchSeconds / count;
        double next = perSample > 0.0 ? kTargetBatchSeconds / perSample : 2.0 * batch;
        if (settings.timeLimitSeconds > 0.0)
            next = std::min(next, std::max(1.0, (settings.timeLimitSeconds - secondsSince(start)) / perSample));
        batch = static_cast<uint32_t>(std::clamp(next, 1.0, 4096.0));
        if (progress) progress({result.samplesDone, settings.samplesPerPixel, secondsSince(start)});
    }
    result.seconds = secondsSince(start);
    return result;
}

ImageRgb resolveFilm(const std::vector<glm::vec4>& sums, uint32_t width, uint32_t height) {
    ImageRgb image;
    image.width = width;
    image.height = height;
    const uint64_t pixels = uint64_t(width) * height;
    image.pixels.resize(pixels * 3);
    for (uint64_t i = 0; i < pixels; ++i) {
        const glm::vec4 s = sums[i];
        const float inv = s.w > 0.0f ? 1.0f / s.w : 0.0f;
        image.pixels[3 * i + 0] = s.x * inv;
        image.pixels[3 * i + 1] = s.y * inv;
        image.pixels[3 * i + 2] = s.z * inv;
    }
    return image;
}

}  // namespace vkp
