// The progressive sample loop shared by the integrators: batches of samples per submission,
// sized towards a target time so that progress, the time limit and Ctrl-C are honoured promptly.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/renderer.h"

namespace vkp {

struct SampleLoopResult {
    uint32_t samplesDone = 0;
    std::string stopReason = "complete";  // "complete", "time limit", "interrupted"
    double seconds = 0.0;
};

// Calls runBatch(firstSample, count) with count <= maxBatch until settings.samplesPerPixel
// samples are done, the time limit passes or `stop` is set.
SampleLoopResult runSampleLoop(const RenderSettings& settings, uint32_t maxBatch, const ProgressCallback& progress,
                               const std::atomic<bool>* stop,
                               const std::function<void(uint32_t firstSample, uint32_t count)>& runBatch);

// The film's per-pixel sums (rgb, sample count) as an image of means.
ImageRgb resolveFilm(const std::vector<glm::vec4>& sums, uint32_t width, uint32_t height);

}  // namespace vkp
