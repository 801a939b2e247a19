// Scrambled Halton sequence: the radical inverse of the sample index in the d-th prime base, with
// a random digit scramble (each digit position gets its own random shift mod base, a bijection on
// digits, so the stratification of the sequence is kept). Seeds come from the pixel (or photon
// stream) and the user's --seed, so sample i of any path can be regenerated from its index alone.
#ifndef VKP_HALTON_GLSL
#define VKP_HALTON_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "hash.glsl"
#include "owen_sobol.glsl"
SHARED_BEGIN

// The first kHaltonDimensions primes.
INLINE uint haltonPrime(uint dimension) {
    switch (dimension) {
    case 0u: return 2u;    case 1u: return 3u;    case 2u: return 5u;    case 3u: return 7u;
    case 4u: return 11u;   case 5u: return 13u;   case 6u: return 17u;   case 7u: return 19u;
    case 8u: return 23u;   case 9u: return 29u;   case 10u: return 31u;  case 11u: return 37u;
    case 12u: return 41u;  case 13u: return 43u;  case 14u: return 47u;  case 15u: return 53u;
    case 16u: return 59u;  case 17u: return 61u;  case 18u: return 67u;  case 19u: return 71u;
    case 20u: return 73u;  case 21u: return 79u;  case 22u: return 83u;  case 23u: return 89u;
    case 24u: return 97u;  case 25u: return 101u; case 26u: return 103u; case 27u: return 107u;
    case 28u: return 109u; case 29u: return 113u; case 30u: return 127u; default: return 131u;
    }
}

// Scrambled radical inverse as an integer fraction digits / limit, limit = base^n >= 2^24, so every
// float-resolution digit is scrambled (also the leading zeros of small indices). Exact integers:
// the host and GPU results are identical.
INLINE uint scrambledRadicalInverseDigits(uint base, uint index, uint scramble, INOUT(uint) limit) {
    uint digits = 0u;
    limit = 1u;
    uint position = 0u;
    while (limit < 16777216u) {
        uint digit = index % base;
        index = index / base;
        uint shift = hashCombine(scramble, position) % base;
        digits = digits * base + (digit + shift) % base;
        limit = limit * base;
        position = position + 1u;
    }
    return digits;
}

INLINE float scrambledRadicalInverse(uint base, uint index, uint scramble) {
    uint limit = 1u;
    uint digits = scrambledRadicalInverseDigits(base, index, scramble, limit);
    return min(float(digits) / float(limit), kOneMinusEpsilon);
}

// A stream of samples for one path. Photon and importon paths (makeSampler): Halton dimensions
// first, then hashed random numbers; path i is the i-th point of one sequence over all paths
// (Keller & Wald's QMC photon tracing, the selective update's groups by the Halton period).
// Camera paths (makePixelSampler): Owen-scrambled Sobol per pixel (owen_sobol.glsl), the sample
// number its index, permuted per dimension within the pixel's sample count.
const uint kSamplerHalton = 0u;
const uint kSamplerOwenSobol = 1u;

struct Sampler {
    uint index;      // sample number (Halton index, or the pixel's sample number)
    uint seed;       // per pixel / per photon stream and per run
    uint dimension;  // next dimension to draw
    uint kind;       // kSamplerHalton or kSamplerOwenSobol
    uint count;      // Owen-Sobol: the pixel's sample count in this stream (permutation size)
};

INLINE Sampler makeSampler(uint index, uint streamSeed) {
    Sampler s;
    s.index = index;
    s.seed = streamSeed;
    s.dimension = 0u;
    s.kind = kSamplerHalton;
    s.count = 1u;
    return s;
}

// Sample `index` of the `count` a pixel takes in the stream `streamSeed` (indices past `count` are
// taken as further blocks of `count`; the stratification holds for each whole block).
INLINE Sampler makePixelSampler(uint index, uint count, uint streamSeed) {
    Sampler s = makeSampler(index, streamSeed);
    s.kind = kSamplerOwenSobol;
    s.count = count;
    return s;
}

INLINE float nextSample(INOUT(Sampler) s) {
    uint scramble = hashCombine(s.seed, s.dimension);
    float value;
    if (s.kind == kSamplerOwenSobol) {
        value = owenSobol1(s.index, s.count, s.seed, s.dimension);
    } else if (s.dimension < kHaltonDimensions) {
        value = scrambledRadicalInverse(haltonPrime(s.dimension), s.index, scramble);
    } else {
        value = uintToUnitFloat(hashCombine(scramble, s.index));
    }
    s.dimension = s.dimension + 1u;
    return value;
}

// Two dimensions at once: a stratified 2-D point for the Sobol sampler.
INLINE vec2 nextSample2(INOUT(Sampler) s) {
    if (s.kind == kSamplerOwenSobol) {
        vec2 value = owenSobol2(s.index, s.count, s.seed, s.dimension);
        s.dimension = s.dimension + 2u;
        return value;
    }
    float a = nextSample(s);
    float b = nextSample(s);
    return vec2(a, b);
}

SHARED_END
#endif
