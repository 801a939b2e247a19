// Exclusive prefix sum of a uint buffer on the GPU (shaders/common/scan_blocks.comp, scan_add.comp):
// blocks of kScanBlockSize items are scanned in workgroup memory, their totals are scanned the
// same way (recursively), and the scanned totals are added back. Three levels cover 16 M items.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "shared/kernels/prefix_scan.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class PrefixScan {
public:
    // Scans the first `count` uints of `data` in place when recorded.
    PrefixScan(vk::Context& context, const vk::Buffer& data, uint32_t count);

    // Records the scan, barriers between its dispatches included; the caller places a barrier
    // before (for the writes that filled `data`) and after.
    void record(VkCommandBuffer cmd) const;

private:
    struct Level {
        uint32_t count;                            // items scanned at this level
        vk::Buffer blockSums;                      // one per block: scanned by the next level
        std::unique_ptr<vk::Kernel<gpu::ScanBlocksKernel>> scan;  // over this level's items
        std::unique_ptr<vk::Kernel<gpu::ScanAddKernel>> add;      // adds the scanned block sums
    };
    std::vector<Level> m_levels;
};

}  // namespace vkp
