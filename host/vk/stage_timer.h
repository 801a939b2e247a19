// GPU time per named stage of recorded work: timestamp queries around each stage's dispatches,
// summed over every recording. The camera passes of a sample (visible points, caustic lookups,
// final gathers) run in one command buffer, so wall-clock time cannot split them; the device's
// timestamps can. A queue without timestamps (timestampValidBits 0) records nothing and reports
// no stages.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace vkp::vk {

class Context;

class StageTimer {
public:
    // Stages are named once; begin/end pairs per recording at most `maxPairs` (over all stages).
    StageTimer(Context& context, std::vector<std::string> stages, uint32_t maxPairs);
    ~StageTimer();
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

    // Starts a recording: adds the previous recording's times (it has completed: the caller
    // waited for its submission) and resets the queries.
    void beginRecording(VkCommandBuffer cmd);
    // Around one stage's dispatches (pairs past maxPairs in one recording are left out).
    void begin(VkCommandBuffer cmd, uint32_t stage);
    void end(VkCommandBuffer cmd, uint32_t stage);
    // Seconds per stage so far, the last recording included (after its submission completed).
    std::vector<double> seconds();
    const std::vector<std::string>& stages() const { return m_stages; }
    bool enabled() const { return m_pool != VK_NULL_HANDLE; }

private:
    void collect();

    Context& m_context;
    std::vector<std::string> m_stages;
    uint32_t m_maxPairs;
    VkQueryPool m_pool = VK_NULL_HANDLE;
    double m_period = 1.0;  // nanoseconds per tick
    uint64_t m_mask = ~uint64_t(0);
    bool m_open = false;                // begin() wrote a timestamp that end() closes
    std::vector<uint32_t> m_pairStage;  // stage of each pair recorded since beginRecording
    std::vector<double> m_seconds;
};

}  // namespace vkp::vk
