// Owen-scrambled Sobol samples for camera paths (Burley, "Practical Hash-based Owen Scrambling",
// JCGT 2020): each dimension (or pair of dimensions) is the first (or first two) Sobol dimension(s)
// of a randomly shuffled sample index, Owen-scrambled by a hash. Every 1-D and 2-D projection is
// then stratified at every power-of-two sample count, and different dimensions get their own index
// shuffle ("padding", after pbrt-v4's PaddedSobolSampler). Known flaw: the shuffle is a nested
// uniform scramble, so an index's low bits still decide every padded dimension's coarsest strata
// (two dimensions share their first bit up to a flip: |r| up to 0.6 over 64 samples); pbrt-v4
// permutes the index within the pixel's sample count instead, which the sampler would need to
// know. Even so it beat Halton and independent random numbers (docs/benchmarks.md). The Halton
// sequence is not fit for a pixel's few samples: at 4-64 spp, dimensions in bases 29..131 see only
// their first digit change, so pairs of them fall on lines, and a path's error per sample rises by
// 1.4-1.6x over independent random numbers (docs/benchmarks.md, issue 17).
#ifndef VKP_OWEN_SOBOL_GLSL
#define VKP_OWEN_SOBOL_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "hash.glsl"
SHARED_BEGIN

// Burley's hash-based Owen scramble of a bit-reversed value (Laine and Karras 2011, improved).
INLINE uint laineKarrasPermutation(uint x, uint seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16u) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

INLINE uint nestedUniformScramble(uint x, uint seed) {
    return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

// Sobol dimension 1 (dimension 0 is the bit-reversed index): generator matrix of x + 1.
INLINE uint sobolSecondDimension(uint index) {
    uint result = 0u;
    uint v = 0x80000000u;
    for (uint bit = 0u; bit < 32u && index != 0u; ++bit) {
        if ((index & 1u) != 0u) result ^= v;
        index >>= 1u;
        v ^= v >> 1u;
    }
    return result;
}

INLINE float unitFromBits(uint bits) {
    return min(float(bits >> 8u) * (1.0f / 16777216.0f), kOneMinusEpsilon);
}

// Dimension `dimension` of sample `index` in the stream `seed`.
INLINE float owenSobol1(uint index, uint seed, uint dimension) {
    uint h = hashCombine(seed, dimension);
    uint shuffled = nestedUniformScramble(index, h);
    return unitFromBits(nestedUniformScramble(bitfieldReverse(shuffled), hashCombine(h, 1u)));
}

// Dimensions `dimension` and `dimension` + 1 of sample `index` as one stratified 2-D point.
INLINE vec2 owenSobol2(uint index, uint seed, uint dimension) {
    uint h = hashCombine(seed, dimension);
    uint shuffled = nestedUniformScramble(index, h);
    return vec2(unitFromBits(nestedUniformScramble(bitfieldReverse(shuffled), hashCombine(h, 1u))),
                unitFromBits(nestedUniformScramble(sobolSecondDimension(shuffled), hashCombine(h, 2u))));
}

SHARED_END
#endif
