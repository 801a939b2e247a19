// Exclusive prefix sum, level one of three: each workgroup scans kScanBlockSize consecutive
// items of `data` in place and writes the block's total to `blockSums` (host/passes/prefix_scan.h).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/prefix_scan.glsl"

layout(local_size_x = kScanGroupSize) in;

layout(std430, set = 0, binding = kScanBlocksDataBinding) buffer Data { uint data[]; };
layout(std430, set = 0, binding = kScanBlocksBlockSumBinding) writeonly buffer BlockSums { uint blockSums[]; };

layout(push_constant) uniform Push { uint count; } push;

shared uint threadTotals[kScanGroupSize];

void main() {
    uint thread = gl_LocalInvocationID.x;
    uint base = gl_WorkGroupID.x * kScanBlockSize + thread * kScanItemsPerThread;
    uint items[kScanItemsPerThread];
    uint sum = 0u;
    for (uint k = 0u; k < kScanItemsPerThread; ++k) {
        uint i = base + k;
        items[k] = i < push.count ? data[i] : 0u;
        sum += items[k];
    }
    // Inclusive Hillis-Steele scan of the per-thread totals.
    threadTotals[thread] = sum;
    barrier();
    for (uint offset = 1u; offset < kScanGroupSize; offset *= 2u) {
        uint add = thread >= offset ? threadTotals[thread - offset] : 0u;
        barrier();
        threadTotals[thread] += add;
        barrier();
    }
    uint running = threadTotals[thread] - sum;  // exclusive prefix of this thread's items
    for (uint k = 0u; k < kScanItemsPerThread; ++k) {
        uint i = base + k;
        if (i < push.count) data[i] = running;
        running += items[k];
    }
    if (thread == kScanGroupSize - 1u) blockSums[gl_WorkGroupID.x] = threadTotals[thread];
}
