// The guiding cache (--guide-cache on): one invocation per (bucket, normal bin) of a coarse grid
// over the guiding photons builds the Jensen grid of the photons in the bucket's first cell whose
// normals fall in the bin, in the bin axis's frame, weighted by flux (the BRDF is left out: exact
// for diffuse surfaces, and the BSDF half of the mixture covers glossy ones), and stores its CDF.
// Direct photons are left out. The bucket's cell is stored so lookups can tell it from other
// cells hashed to the same bucket.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/guiding.glsl"
#include "shared/photon.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer CellStart { uint cellStart[]; };
layout(std430, set = 0, binding = 1) readonly buffer GridPhotons { GpuPhoton gridPhotons[]; };
layout(std430, set = 0, binding = 2) writeonly buffer CacheCells { ivec4 cacheCells[]; };  // xyz cell, w 1: used
layout(std430, set = 0, binding = 3) writeonly buffer CacheCdfs { float cacheCdfs[]; };    // kMaxGuideCells each

layout(push_constant) uniform Push { GuideParams guide; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    uint bucket = index / kGuideNormalBins;
    uint bin = index - bucket * kGuideNormalBins;
    if (bucket > guide.grid.tableMask) return;
    uint gm = guide.gridSize & 0xffu;
    uint gn = guide.gridSize >> 8u;
    uint begin = cellStart[bucket];
    uint end = cellStart[bucket + 1u];
    ivec3 cell = begin < end ? gridCell(gridPhotons[begin].position, guide.grid.invCellSize) : ivec3(0);
    if (bin == 0u) cacheCells[bucket] = ivec4(cell, begin < end ? 1 : 0);

    float cells[kMaxGuideCells];
    for (uint i = 0u; i < kMaxGuideCells; ++i) cells[i] = 0.0f;
    vec3 axis = guideBinNormal(bin);
    vec3 t;
    vec3 b;
    orthonormalBasis(axis, t, b);
    for (uint i = begin; i < end; ++i) {
        GpuPhoton p = gridPhotons[i];
        if ((photonFlags(p) & kPhotonPrimary) != 0u || gridCell(p.position, guide.grid.invCellSize) != cell ||
            guideNormalBin(decodeOctahedral(p.normal)) != bin)
            continue;
        guideAdd(cells, gm, gn, toLocal(decodeOctahedral(p.direction), t, b, axis), luminance(photonRelativePower(p)));
    }
    guideFinalize(cells, gm, gn);
    for (uint i = 0u; i < kMaxGuideCells; ++i) cacheCdfs[index * kMaxGuideCells + i] = cells[i];
}
