// For every importon slot: what importance_lookup.comp reads at a photon, read at the importon
// instead (x: importance density, y: largest path importance; zeros for empty slots). The host
// sets Keller & Wald's scale f from the least density the directly seen importons sense
// (host/photon/importon_map.cpp).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/importons.glsl"
#include "shared/importance.glsl"

layout(local_size_x = kImportonGroupSize) in;

layout(std430, set = 0, binding = kImportanceLookupTableBinding) readonly buffer Table { ImportanceCell table[]; };
layout(std430, set = 0, binding = kImportanceLookupSlotBinding) readonly buffer Importons { GpuImporton importons[]; };
layout(std430, set = 0, binding = kImportanceLookupImportanceBinding) writeonly buffer Importance { vec2 importance[]; };  // density, max path importance

layout(push_constant) uniform Push { ImportanceGridParams params; };

#include "photon/importance_lookup.glsl"

void main() {
    uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.slotCount) return;
    GpuImporton p = importons[slot];
    vec2 result = vec2(0.0f);
    if ((p.flags & kImportonValid) != 0u) result = importanceAround(p.position, decodeOctahedral(p.normal));
    importance[slot] = result;
}
