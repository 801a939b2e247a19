// Exclusive prefix sum, last step: adds each block's scanned offset to its items.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/prefix_scan.glsl"
#include "common/item_index.glsl"

layout(local_size_x = kScanGroupSize) in;

layout(std430, set = 0, binding = kScanAddDataBinding) buffer Data { uint data[]; };
layout(std430, set = 0, binding = kScanAddBlockSumBinding) readonly buffer BlockOffsets { uint blockOffsets[]; };

layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = itemIndex();
    if (i < push.count) data[i] += blockOffsets[i / kScanBlockSize];
}
