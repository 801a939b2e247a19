#include "vk/stage_timer.h"

#include <stdexcept>

#include "vk/check.h"
#include "vk/context.h"

namespace vkp::vk {

StageTimer::StageTimer(Context& context, std::vector<std::string> stages, uint32_t maxPairs)
    : m_context(context), m_stages(std::move(stages)), m_maxPairs(maxPairs), m_seconds(m_stages.size(), 0.0) {
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &families, nullptr);
    std::vector<VkQueueFamilyProperties> properties(families);
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &families, properties.data());
    const uint32_t validBits = context.queueFamily() < families ? properties[context.queueFamily()].timestampValidBits : 0;
    if (validBits == 0 || maxPairs == 0) return;
    if (validBits < 64) m_mask = (uint64_t(1) << validBits) - 1;
    m_period = context.properties().limits.timestampPeriod;
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * maxPairs;
    check(vkCreateQueryPool(context.device(), &info, nullptr, &m_pool), "creating the stage timer's query pool");
}

StageTimer::~StageTimer() {
    if (m_pool) vkDestroyQueryPool(m_context.device(), m_pool, nullptr);
}

void StageTimer::collect() {
    if (!m_pool || m_pairStage.empty()) return;
    std::vector<uint64_t> ticks(2 * m_pairStage.size());
    const VkResult result = vkGetQueryPoolResults(m_context.device(), m_pool, 0, static_cast<uint32_t>(ticks.size()),
                                                  ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                                  VK_QUERY_RESULT_64_BIT);
    if (result == VK_SUCCESS)
        for (size_t i = 0; i < m_pairStage.size(); ++i) {
            const uint64_t elapsed = ((ticks[2 * i + 1] & m_mask) - (ticks[2 * i] & m_mask)) & m_mask;
            m_seconds[m_pairStage[i]] += double(elapsed) * m_period * 1e-9;
        }
    m_pairStage.clear();
}

void StageTimer::beginRecording(VkCommandBuffer cmd) {
    if (!m_pool) return;
    collect();
    vkCmdResetQueryPool(cmd, m_pool, 0, 2 * m_maxPairs);
}

void StageTimer::begin(VkCommandBuffer cmd, uint32_t stage) {
    if (stage >= m_stages.size()) throw std::logic_error("StageTimer: no such stage");
    m_open = false;
    if (!m_pool || m_pairStage.size() >= m_maxPairs) return;
    m_open = true;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, m_pool, uint32_t(2 * m_pairStage.size()));
    m_pairStage.push_back(stage);
}

void StageTimer::end(VkCommandBuffer cmd, uint32_t stage) {
    if (!m_open || m_pairStage.back() != stage) return;
    m_open = false;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, m_pool, uint32_t(2 * m_pairStage.size() - 1));
}

std::vector<double> StageTimer::seconds() {
    collect();
    return m_seconds;
}

}  // namespace vkp::vk
