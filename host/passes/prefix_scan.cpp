#include "passes/prefix_scan.h"

namespace vkp {

PrefixScan::PrefixScan(vk::Context& context, const vk::Buffer& data, uint32_t count) {
    m_levels.reserve(4);
    const vk::Buffer* items = &data;
    uint32_t n = count;
    while (n > 0) {
        Level level;
        level.count = n;
        const uint32_t blocks = vk::groupCount(n, gpu::kScanBlockSize);
        level.blockSums = vk::Buffer(context, "scan block sums", std::max<VkDeviceSize>(16, blocks * sizeof(uint32_t)),
                                     vk::kStorageUsage);
        level.scan = std::make_unique<vk::Kernel<gpu::ScanBlocksKernel>>(context);
        level.scan->bind(gpu::kScanBlocksDataBinding, *items);
        level.scan->bind(gpu::kScanBlocksBlockSumBinding, level.blockSums);
        level.add = std::make_unique<vk::Kernel<gpu::ScanAddKernel>>(context);
        level.add->bind(gpu::kScanAddDataBinding, *items);
        level.add->bind(gpu::kScanAddBlockSumBinding, level.blockSums);
        m_levels.push_back(std::move(level));
        items = &m_levels.back().blockSums;
        n = blocks > 1 ? blocks : 0;  // a single block's total needs no further scan
    }
}

void PrefixScan::record(VkCommandBuffer cmd) const {
    for (const Level& level : m_levels) {
        // A workgroup scans a block of kScanBlockSize items: one invocation per kScanItemsPerThread.
        level.scan->record(cmd, vk::groupCount(level.count, gpu::kScanItemsPerThread), level.count);
        vk::computeBarrier(cmd);
    }
    // Back down: level i's block sums are now scanned (by level i + 1), add them to its items.
    for (size_t i = m_levels.size(); i-- > 1;) {
        const Level& level = m_levels[i - 1];
        level.add->record(cmd, level.count, level.count);
        vk::computeBarrier(cmd);
    }
}

}  // namespace vkp
