// Owen-scrambled Sobol samples for camera paths (Burley, "Practical Hash-based Owen Scrambling",
// JCGT 2020), padded as pbrt-v4's PaddedSobolSampler pads them: each dimension (or pair of
// dimensions) is the first (or first two) Sobol dimension(s) of the pixel's sample number, randomly
// permuted within the pixel's sample count (Kensler's hashed permutation, "Correlated Multi-Jittered
// Sampling", 2013) and Owen-scrambled by a hash, both seeded per dimension. The n samples of a
// pixel are then stratified in every 1-D and 2-D projection (n a power of two: one point per
// elementary 2-D interval), and different dimensions are paired by independent permutations, so no
// two of them are correlated. Sample numbers beyond the count are permuted within their own block
// of `count` numbers. A nested-uniform scramble of the sample number (this file's first padding)
// is not enough: it keeps the number's low bits as every dimension's coarsest strata, so two
// dimensions shared their first bit up to a flip (|r| up to 0.6 over 64 samples). The Halton
// sequence is not fit for a pixel's few samples: at 4-64 spp, dimensions in bases 29..131 see only
// their first digit change, so pairs of them fall on lines, and a path's error per sample rises by
// 1.4-1.6x over independent random numbers (docs/benchmarks.md).
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

// Element `i` of a random permutation of 0..n-1 chosen by `seed` (Kensler 2013: a hashed bijection
// on the next power of two, walked until it lands below n; each step lands with probability > 1/2,
// and the walk is bounded for lavapipe's loop budget: after 32 misses, which happen with
// probability below 2^-32, i is kept, so the map is still a bijection's prefix for every i < n
// that landed).
INLINE uint permutationElement(uint i, uint n, uint seed) {
    uint mask = n - 1u;
    mask |= mask >> 1u;
    mask |= mask >> 2u;
    mask |= mask >> 4u;
    mask |= mask >> 8u;
    mask |= mask >> 16u;
    uint start = i;
    for (uint step = 0u; step < 32u; ++step) {
        i ^= seed;
        i *= 0xe170893du;
        i ^= seed >> 16u;
        i ^= (i & mask) >> 4u;
        i ^= seed >> 8u;
        i *= 0x0929eb3fu;
        i ^= seed >> 23u;
        i ^= (i & mask) >> 1u;
        i *= 1u | (seed >> 27u);
        i *= 0x6935fa69u;
        i ^= (i & mask) >> 11u;
        i *= 0x74dcb303u;
        i ^= (i & mask) >> 2u;
        i *= 0x9e501cc3u;
        i ^= (i & mask) >> 2u;
        i *= 0xc860a3dfu;
        i &= mask;
        i ^= i >> 5u;
        if (i < n) return (i + seed) % n;
    }
    return start;
}

// The sample number that dimension-stream `h` reads for sample `index` of a pixel taking `count`
// samples: a permutation within index's block of `count` numbers. A count that is not known (0)
// or past 2^16 — a render that runs until a time limit, given a huge --spp — takes blocks that
// double instead, [1, 2), [2, 4), [4, 8), ..., each permuted on its own: the first 2^k samples of
// a pixel are then the first 2^k Sobol numbers, a stratified set, wherever the render stops, and
// each block spans every stratum of every dimension, so dimensions stay decorrelated. (One block
// of 2^16 or of the whole count made a few samples a random subset of many: not stratified.)
INLINE uint permutedSampleNumber(uint index, uint count, uint h) {
    if (count == 0u || count > 65536u) {
        if (index < 2u) return index;
        uint start = 1u << uint(findMSB(index));
        return start + permutationElement(index - start, start, hashCombine(h, start));
    }
    uint block = index / count;
    uint first = block * count;
    return first + permutationElement(index - first, count, hashCombine(h, block));
}

// Dimension `dimension` of sample `index` of `count` in the stream `seed`.
INLINE float owenSobol1(uint index, uint count, uint seed, uint dimension) {
    uint h = hashCombine(seed, dimension);
    uint number = permutedSampleNumber(index, count, h);
    return unitFromBits(nestedUniformScramble(bitfieldReverse(number), hashCombine(h, 1u)));
}

// Dimensions `dimension` and `dimension` + 1 of sample `index` of `count` as one stratified 2-D point.
INLINE vec2 owenSobol2(uint index, uint count, uint seed, uint dimension) {
    uint h = hashCombine(seed, dimension);
    uint number = permutedSampleNumber(index, count, h);
    return vec2(unitFromBits(nestedUniformScramble(bitfieldReverse(number), hashCombine(h, 1u))),
                unitFromBits(nestedUniformScramble(sobolSecondDimension(number), hashCombine(h, 2u))));
}

SHARED_END
#endif
