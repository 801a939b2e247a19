// Interface of the prefix-sum kernels scan_blocks.comp and scan_add.comp (host/passes/prefix_scan.h).
#ifndef VKP_KERNELS_PREFIX_SCAN_GLSL
#define VKP_KERNELS_PREFIX_SCAN_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

// A scan block holds kScanItemsPerThread items per invocation.
const uint kScanGroupSize = 64u;
const uint kScanItemsPerThread = 4u;
const uint kScanBlockSize = 256u;  // kScanGroupSize * kScanItemsPerThread

// scan_blocks.comp
const uint kScanBlocksDataBinding = 0u;      // uint: the items, scanned in place per block
const uint kScanBlocksBlockSumBinding = 1u;  // uint per block: its total
// scan_add.comp
const uint kScanAddDataBinding = 0u;         // uint: the items
const uint kScanAddBlockSumBinding = 1u;     // uint per block: its scanned offset, added to its items

SHARED_END

#ifdef __cplusplus
namespace vkp::gpu {

static_assert(kScanBlockSize == kScanGroupSize * kScanItemsPerThread);

// Push constants of both: the number of items.
struct ScanBlocksKernel {
    static constexpr const char* kShader = "scan_blocks.comp";
    static constexpr uint32_t kBindingCount = kScanBlocksBlockSumBinding + 1u;
    static constexpr uint32_t kGroupSize = kScanGroupSize;
    using Push = uint32_t;
};
struct ScanAddKernel {
    static constexpr const char* kShader = "scan_add.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): maps past 4 M photons
    static constexpr uint32_t kBindingCount = kScanAddBlockSumBinding + 1u;
    static constexpr uint32_t kGroupSize = kScanGroupSize;
    using Push = uint32_t;
};

}  // namespace vkp::gpu
#endif
#endif
