// The environment light (kLightEnvironment, docs/environment.md): radiance arriving from infinitely
// far away in every direction, a constant or an equirectangular map, and its importance sampling
// by a 2-D piecewise-constant distribution of luminance x sin(theta) (pbrt's Distribution2D),
// built on the host (host/scene/environment_distribution.h) and stored as floats:
//
//   [0, 3 W H)          RGB radiance per pixel (strength applied), row-major, top row first
//   [3 W H, 4 W H)      conditional CDF of each row (inclusive prefix sums, last of a row = 1)
//   [4 W H, 4 W H + H)  marginal CDF over the rows (inclusive, last = 1)
//
// Mapping (Blender's equirectangular in glTF axes, +Y up): u = atan2(z, x) / 2 pi + 0.5 (the centre
// column faces +X, u = 0.75 faces +Z), t = acos(y) / pi from the top row (the zenith, +Y). The map
// is turned by `rotation` radians about +Y (right-handed): at 90 degrees what faced +X faces -Z.
//
// The functions read the data through ENV_FLOAT(i) (index relative to the map's first float): the
// GLSL includer defines it over its buffer; C++ passes `const float* envData` (ENV_DATA_PARAM).
#ifndef VKP_ENVIRONMENT_GLSL
#define VKP_ENVIRONMENT_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "sampling.glsl"
SHARED_BEGIN

#ifdef __cplusplus
#define ENV_DATA_PARAM const float *envData,
#define ENV_DATA_ARG envData,
#define ENV_FLOAT(i) envData[(i)]
#else
#define ENV_DATA_PARAM
#define ENV_DATA_ARG
#endif

// Longest binary search: maps have at most 2^16 columns or rows.
const uint kEnvironmentSearchSteps = 20u;

// A map's shape as the light stores it; width 0 means a constant environment.
struct EnvironmentMap {
    uint offset;      // first float of the map's data (in ENV_FLOAT's index space)
    uint width;
    uint height;
    float rotation;   // radians about +Y
};

// World direction -> direction in the map's frame (turned back by the rotation).
INLINE vec3 environmentToMap(vec3 d, float rotation) {
    float c = cos(rotation);
    float s = sin(rotation);
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

INLINE vec3 environmentFromMap(vec3 d, float rotation) {
    float c = cos(rotation);
    float s = sin(rotation);
    return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

// Map-frame direction -> (u, t) in [0, 1]^2: u across (0.5 = +X, 0.75 = +Z), t down from +Y.
INLINE vec2 environmentUv(vec3 d) {
    float u = atan(d.z, d.x) * (0.5f * kInvPi) + 0.5f;
    float t = acos(clamp(d.y, -1.0f, 1.0f)) * kInvPi;
    return vec2(clamp(u, 0.0f, kOneMinusEpsilon), clamp(t, 0.0f, kOneMinusEpsilon));
}

INLINE vec3 environmentDirection(vec2 uv) {
    float phi = kTwoPi * (uv.x - 0.5f);
    float theta = kPi * uv.y;
    float st = sin(theta);
    return vec3(st * cos(phi), cos(theta), st * sin(phi));
}

// Radiance of the map's pixel (i, j).
INLINE vec3 environmentTexel(ENV_DATA_PARAM EnvironmentMap map, uint i, uint j) {
    uint k = map.offset + 3u * (j * map.width + i);
    return vec3(ENV_FLOAT(k), ENV_FLOAT(k + 1u), ENV_FLOAT(k + 2u));
}

INLINE uvec2 environmentPixel(EnvironmentMap map, vec2 uv) {
    return uvec2(min(uint(uv.x * float(map.width)), map.width - 1u), min(uint(uv.y * float(map.height)), map.height - 1u));
}

// Radiance of a map arriving from world direction d (nearest pixel: the distribution's pieces).
INLINE vec3 environmentMapRadiance(ENV_DATA_PARAM EnvironmentMap map, vec3 d) {
    uvec2 p = environmentPixel(map, environmentUv(environmentToMap(d, map.rotation)));
    return environmentTexel(ENV_DATA_ARG map, p.x, p.y);
}

// First index k in [first, first + count) with u < cdf[k] (inclusive prefix sums, last = 1).
INLINE uint environmentSearch(ENV_DATA_PARAM uint first, uint count, float u) {
    uint lo = 0u;
    uint hi = count - 1u;
    for (uint step = 0u; step < kEnvironmentSearchSteps && lo < hi; ++step) {
        uint mid = (lo + hi) / 2u;
        if (u < ENV_FLOAT(first + mid)) hi = mid; else lo = mid + 1u;
    }
    return lo;
}

// Probability of piece k of a CDF stored from `first`.
INLINE float environmentPiece(ENV_DATA_PARAM uint first, uint k) {
    float below = k > 0u ? ENV_FLOAT(first + k - 1u) : 0.0f;
    return ENV_FLOAT(first + k) - below;
}

// Solid-angle pdf with which environmentMapSample returns world direction d.
INLINE float environmentMapPdf(ENV_DATA_PARAM EnvironmentMap map, vec3 d) {
    vec2 uv = environmentUv(environmentToMap(d, map.rotation));
    float sinTheta = sin(kPi * uv.y);
    if (sinTheta <= 0.0f) return 0.0f;
    uvec2 p = environmentPixel(map, uv);
    uint pixels = map.width * map.height;
    float pRow = environmentPiece(ENV_DATA_ARG map.offset + 4u * pixels, p.y);
    float pColumn = environmentPiece(ENV_DATA_ARG map.offset + 3u * pixels + p.y * map.width, p.x);
    float pdfUv = pRow * float(map.height) * pColumn * float(map.width);
    return pdfUv / (2.0f * kPi * kPi * sinTheta);
}

// A direction drawn from the map's distribution: returns the world direction; radiance and the
// solid-angle pdf through the out-parameters (pdf 0: no sample).
INLINE vec3 environmentMapSample(ENV_DATA_PARAM EnvironmentMap map, vec2 u, OUT(vec3) radiance, OUT(float) pdf) {
    uint pixels = map.width * map.height;
    uint marginal = map.offset + 4u * pixels;
    uint j = environmentSearch(ENV_DATA_ARG marginal, map.height, u.x);
    float pRow = environmentPiece(ENV_DATA_ARG marginal, j);
    float rowBelow = j > 0u ? ENV_FLOAT(marginal + j - 1u) : 0.0f;
    uint conditional = map.offset + 3u * pixels + j * map.width;
    uint i = environmentSearch(ENV_DATA_ARG conditional, map.width, u.y);
    float pColumn = environmentPiece(ENV_DATA_ARG conditional, i);
    float columnBelow = i > 0u ? ENV_FLOAT(conditional + i - 1u) : 0.0f;
    radiance = vec3(0.0f);
    pdf = 0.0f;
    if (pRow <= 0.0f || pColumn <= 0.0f) return vec3(0.0f, 1.0f, 0.0f);
    float fu = clamp((u.y - columnBelow) / pColumn, 0.0f, kOneMinusEpsilon);
    float fv = clamp((u.x - rowBelow) / pRow, 0.0f, kOneMinusEpsilon);
    vec2 uv = vec2((float(i) + fu) / float(map.width), (float(j) + fv) / float(map.height));
    float sinTheta = sin(kPi * uv.y);
    if (sinTheta <= 0.0f) return vec3(0.0f, 1.0f, 0.0f);
    radiance = environmentTexel(ENV_DATA_ARG map, i, j);
    pdf = pRow * float(map.height) * pColumn * float(map.width) / (2.0f * kPi * kPi * sinTheta);
    return environmentFromMap(environmentDirection(uv), map.rotation);
}

SHARED_END
#endif
