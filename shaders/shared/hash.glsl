// Integer hashing for decorrelating samplers. Pure integer arithmetic: the host and the GPU agree
// bit for bit.
#ifndef VKP_HASH_GLSL
#define VKP_HASH_GLSL
#include "compat.glsl"
SHARED_BEGIN

// PCG-based hash (Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 2020).
INLINE uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

INLINE uint hashCombine(uint seed, uint v) {
    return pcgHash(seed ^ (v + 0x9e3779b9u + (seed << 6u) + (seed >> 2u)));
}

// A uniform float in [0, 1) from the top 24 bits of a hash (exact on both sides).
INLINE float uintToUnitFloat(uint h) {
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

SHARED_END
#endif
