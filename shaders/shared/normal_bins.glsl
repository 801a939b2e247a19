// Six normal bins, one per axis direction: a surface normal belongs to the axis it is closest
// to. Keeps per-cell data of the two sides of a wall (and of a room's perpendicular walls)
// apart: the guiding cache's grids and the importance grid's cells.
#ifndef VKP_NORMAL_BINS_GLSL
#define VKP_NORMAL_BINS_GLSL
#include "compat.glsl"
SHARED_BEGIN

const uint kNormalBins = 6u;

INLINE uint normalBin(vec3 n) {
    vec3 a = abs(n);
    if (a.x >= a.y && a.x >= a.z) return n.x >= 0.0f ? 0u : 1u;
    if (a.y >= a.z) return n.y >= 0.0f ? 2u : 3u;
    return n.z >= 0.0f ? 4u : 5u;
}

// The axis direction of a bin.
INLINE vec3 normalBinAxis(uint bin) {
    float s = (bin & 1u) == 0u ? 1.0f : -1.0f;
    uint axis = bin / 2u;
    return vec3(axis == 0u ? s : 0.0f, axis == 1u ? s : 0.0f, axis == 2u ? s : 0.0f);
}

SHARED_END
#endif
