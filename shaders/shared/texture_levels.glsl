// Where a texture's mipmap levels lie in its rectangle of the texture atlas
// (host/gpu_scene/texture_atlas.h), shared by the atlas builder and the shader's lookup
// (scene_access.glsl sampleTexture) so both place level L at the same texels.
//
// Level 0 is the image (w x h). Each further level halves the one before, rounding up, as the
// atlas's 2x2 box filter does (halveTexture): level L is ((w - 1) >> L) + 1 wide and
// ((h - 1) >> L) + 1 high, down to 1 x 1. Levels 1.. stand in one column right of level 0, level 1
// at the top:
//
//     +---------+-----+
//     |         |  1  |
//     |    0    +--+--+
//     |         |2 |
//     +---------+--+
//
// so the rectangle is w + width(1) wide and max(h, the column's height) high (about 1.5 w x h).
#ifndef VKP_TEXTURE_LEVELS_GLSL
#define VKP_TEXTURE_LEVELS_GLSL
#include "compat.glsl"
SHARED_BEGIN

// Bits needed to write n (0 for 0): the halvings after which an axis of n + 1 texels is 1 texel.
INLINE uint bitLength(uint n) {
    return n == 0u ? 0u : uint(findMSB(n)) + 1u;
}

// Levels of a full chain for a w x h image: 1 + the halvings until both axes are 1.
INLINE uint mipLevelCount(uint w, uint h) {
    return 1u + max(bitLength(w - 1u), bitLength(h - 1u));
}

// Texels along an axis of n (>= 1) at `level`.
INLINE uint mipLevelSize(uint n, uint level) {
    return ((n - 1u) >> level) + 1u;
}

// Rows above `level` (>= 1) in the column of levels 1..: the sum of the heights of levels
// 1..level-1, in closed form (no loop). With m = h - 1, level k is (m >> k) + 1 high, and
// sum_{k=1..j} (m >> k) = (m - bitCount(m)) - ((m >> j) - bitCount(m >> j)).
INLINE uint mipLevelRow(uint h, uint level) {
    if (level <= 1u) return 0u;
    uint m = h - 1u;
    uint j = level - 1u;
    uint tail = m >> j;
    return j + (m - uint(bitCount(m))) - (tail - uint(bitCount(tail)));
}

// Column of `level`'s first texel in the rectangle (0 for level 0, w for the others).
INLINE uint mipLevelColumn(uint w, uint level) {
    return level == 0u ? 0u : w;
}

// The size of the rectangle holding levels 0..levels-1 of a w x h image.
INLINE uint mipRectWidth(uint w, uint levels) {
    return levels <= 1u ? w : w + mipLevelSize(w, 1u);
}

INLINE uint mipRectHeight(uint h, uint levels) {
    return levels <= 1u ? h : max(h, mipLevelRow(h, levels));
}

SHARED_END
#endif
