// Builds the importance grid (shared/importance.glsl): every importon adds itself to its cell at
// every level, in the normal bin of its surface. Integer atomics only, so the sums are the same
// on every run whatever the order.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/importons.glsl"
#include "shared/normal_bins.glsl"
#include "shared/importance.glsl"
#include "shared/photon.glsl"

layout(local_size_x = kImportonGroupSize) in;

layout(std430, set = 0, binding = kImportanceSplatImportonBinding) readonly buffer Importons { GpuImporton importons[]; };
layout(std430, set = 0, binding = kImportanceSplatTableBinding) buffer Table { ImportanceCell table[]; };

layout(push_constant) uniform Push { ImportanceGridParams params; };

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount) return;
    GpuImporton p = importons[slot];
    if ((p.flags & kImportonValid) == 0u) return;
    uint importance = uint(min(p.importance, kMaxImportonImportance) * kImportanceFixedPoint + 0.5f);
    uint pathImportance = floatBitsToUint(max(p.pathImportance, 0.0f));
    uint bin = normalBin(decodeOctahedral(p.normal));
    for (uint level = 0u; level < kImportanceLevels; ++level) {
        ivec3 c = importanceCell(p.position, params.invCellSize, level);
        uint key = importanceKey(c, level, bin);
        uint index = importanceSlotHash(c, level, bin) & params.tableMask;
        for (uint probe = 0u; probe < kImportanceMaxProbes; ++probe) {
            uint previous = atomicCompSwap(table[index].key, kImportanceEmptyKey, key);
            if (previous == kImportanceEmptyKey || previous == key) {
                atomicAdd(table[index].count, 1u);
                atomicAdd(table[index].importance, importance);
                atomicMax(table[index].maxPathImportance, pathImportance);
                break;
            }
            index = (index + 1u) & params.tableMask;
        }
    }
}
