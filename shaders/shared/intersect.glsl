// Ray/triangle and ray/box tests of the BVH traversal (bvh_traverse.glsl, compiled for the GPU and
// for the host BVH in host/bvh/bvh.cpp): the host compile is the reference the GPU must match.
#ifndef VKP_INTERSECT_GLSL
#define VKP_INTERSECT_GLSL
#include "compat.glsl"
#include "constants.glsl"

// `precise` forbids the shader compiler from fusing a*b - c*d into an FMA (SPIR-V NoContraction).
// A fused edge function is no longer exactly antisymmetric in its two vertices, so two triangles
// sharing an edge could both reject a ray through it: watertightness needs unfused arithmetic.
// On the host, clang is told so inside intersectTriangle; GCC (12, even with -std=c++20) fuses
// whenever the target has FMA (-march=native, aarch64), so such host builds need
// -ffp-contract=off. The x86-64 baseline has no FMA. tests/bvh/bvh_test.cpp catches a fused build:
// with -mfma and no contraction control, 396 of 20000 rays slip out of a closed mesh.
#ifndef VKP_PRECISE
#ifdef __cplusplus
#define VKP_PRECISE
#else
#define VKP_PRECISE precise
#endif
#endif

SHARED_BEGIN

// Watertight ray/triangle intersection: Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013 (Listing 1, without back-face culling).
//
// The triangle is translated to the ray origin, permuted so the ray's dominant axis becomes z
// (kz; kx/ky swapped when dir[kz] < 0 to keep the winding), and sheared so the ray runs along +z.
// The 2-D edge functions u, v, w then depend only on the two vertices of their edge and on
// per-ray constants, so a triangle and its neighbour compute the same value (with opposite sign)
// on a shared edge: a ray can never slip between them. Exact zeros (ray through an edge or a
// vertex) are accepted by both sides. The paper re-evaluates zero edge functions in double
// precision; GLSL has no portable double, so both sides accept instead (never a gap, at worst a
// tie resolved by traversal order).
//
// Watertight is not exact: the translated vertices carry absolute errors of ~1e-7 times their
// distance from the origin, so a triangle smaller than that (edges below ~1e-7 x distance) is
// below float resolution and may be missed or reported hit anywhere near its plane.
//
// Hits with 0 < t < tMax (strict, so a running tMax keeps the first of equal hits) write t and
// the barycentrics (b1, b2) of v1 and v2; v0's is 1 - b1 - b2. The conditions are written so a NaN
// anywhere (e.g. a zero direction) is a miss.
INLINE bool intersectTriangle(vec3 org, vec3 dir, vec3 v0, vec3 v1, vec3 v2, float tMax,
                              INOUT(float) tOut, INOUT(float) b1Out, INOUT(float) b2Out) {
#if defined(__cplusplus) && defined(__clang__)
#pragma clang fp contract(off)  // clang fuses a*b - c*d by default where FMA exists; see VKP_PRECISE
#endif
    float adx = abs(dir.x);
    float ady = abs(dir.y);
    float adz = abs(dir.z);
    int kz = adx > ady ? (adx > adz ? 0 : 2) : (ady > adz ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (dir[kz] < 0.0f) {
        int tmp = kx;
        kx = ky;
        ky = tmp;
    }
    // Shear constants (paper section 3): per ray, identical for every triangle it is tested against.
    VKP_PRECISE float sz = 1.0f / dir[kz];
    VKP_PRECISE float sx = dir[kx] * sz;
    VKP_PRECISE float sy = dir[ky] * sz;

    VKP_PRECISE vec3 a = v0 - org;
    VKP_PRECISE vec3 b = v1 - org;
    VKP_PRECISE vec3 c = v2 - org;
    VKP_PRECISE float ax = a[kx] - sx * a[kz];
    VKP_PRECISE float ay = a[ky] - sy * a[kz];
    VKP_PRECISE float bx = b[kx] - sx * b[kz];
    VKP_PRECISE float by = b[ky] - sy * b[kz];
    VKP_PRECISE float cx = c[kx] - sx * c[kz];
    VKP_PRECISE float cy = c[ky] - sy * c[kz];

    // Scaled barycentrics: u is the weight of v0 (edge v1-v2), v of v1, w of v2.
    VKP_PRECISE float u = cx * by - cy * bx;
    VKP_PRECISE float v = ax * cy - ay * cx;
    VKP_PRECISE float w = bx * ay - by * ax;
    bool anyNegative = u < 0.0f || v < 0.0f || w < 0.0f;
    bool anyPositive = u > 0.0f || v > 0.0f || w > 0.0f;
    if (anyNegative && anyPositive) return false;

    VKP_PRECISE float det = u + v + w;
    if (!(det < 0.0f || det > 0.0f)) return false;  // parallel, degenerate or NaN

    // Scaled distance T = det * t. The paper compares T with det * tMax to skip the division for
    // misses, but that rounds differently from t < tMax and makes the closest of two hits a few
    // ulps apart depend on the order they are tested in (BVH vs brute force); dividing first makes
    // "closest" exactly the minimum t. Only rays whose line passes through the triangle get here.
    VKP_PRECISE float az = sz * a[kz];
    VKP_PRECISE float bz = sz * b[kz];
    VKP_PRECISE float cz = sz * c[kz];
    VKP_PRECISE float t = u * az + v * bz + w * cz;
    if (det < 0.0f ? !(t < 0.0f) : !(t > 0.0f)) return false;  // behind the origin

    float invDet = 1.0f / det;
    float tHit = t * invDet;
    if (!(tHit > 0.0f && tHit < tMax)) return false;
    tOut = tHit;
    b1Out = v * invDet;
    b2Out = w * invDet;
    return true;
}

// Direction components smaller than this are treated as this (with their sign) by the slab test.
const float kMinDirectionComponent = 1.0e-30f;

// Per-ray inverse direction for intersectAabb. A zero component would give 1/0 = inf and then
// 0 * inf = NaN for a box face through the origin, and GLSL leaves min/max of NaN undefined (and
// drivers may assume no NaNs). A finite 1e30 instead gives slab distances of +-1e30 * gap (or
// +-inf after overflow, never NaN). Only components below 1e-30 change, i.e. rays that move less
// than 1e-30 * t along that axis; -0 is treated as +0 (the slab test is symmetric in the sign).
//
// What this cannot express: a ray with a zero component lying exactly in a face plane of a box
// (gap 0) gets slab distance 0 there and may be culled, although it runs along the face. The BVH
// builder therefore pads every node box outward (host/bvh/bvh.cpp: at least one ulp and 1e-20),
// so the gap to any triangle's plane is >= 1e-20 and the slab extends >= 1e10 along the ray: a
// box is only culled this way when the ray cannot touch the geometry inside it.
INLINE vec3 safeInverseDirection(vec3 dir) {
    float dx = abs(dir.x) >= kMinDirectionComponent ? dir.x
             : (dir.x < 0.0f ? -kMinDirectionComponent : kMinDirectionComponent);
    float dy = abs(dir.y) >= kMinDirectionComponent ? dir.y
             : (dir.y < 0.0f ? -kMinDirectionComponent : kMinDirectionComponent);
    float dz = abs(dir.z) >= kMinDirectionComponent ? dir.z
             : (dir.z < 0.0f ? -kMinDirectionComponent : kMinDirectionComponent);
    vec3 inv;
    inv.x = 1.0f / dx;
    inv.y = 1.0f / dy;
    inv.z = 1.0f / dz;
    return inv;
}

// Relative widening of the slab exit distance so rounding never culls a box the ray touches:
// Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013, uses 1 + 2 gamma(3) (~1 + 3.6e-7) for
// correctly rounded arithmetic; Vulkan allows 2.5 ulp for the division in safeInverseDirection,
// so the GPU error bound is about twice that. Culling is then conservative on both sides.
const float kAabbExitScale = 1.000001f;

// Slab test (Kay and Kajiya 1986) with a precomputed inverse direction (safeInverseDirection).
// Returns the entry distance, clamped to >= 0 for an origin inside the box, when the ray overlaps
// the box within [0, tMax]; otherwise kInfinity. (b - org) * invDir, not the fma form
// b * invDir - org * invDir, keeps the rounding error relative to t, which Ize's bound needs.
// The test is symmetric in bmin/bmax, so an inverted box is no way to encode "empty" (the
// traversal checks the empty tree explicitly, see bvh_traverse.glsl).
INLINE float intersectAabb(vec3 org, vec3 invDir, vec3 bmin, vec3 bmax, float tMax) {
    vec3 t0 = (bmin - org) * invDir;
    vec3 t1 = (bmax - org) * invDir;
    vec3 tn = min(t0, t1);
    vec3 tf = max(t0, t1);
    float tNear = max(max(tn.x, tn.y), max(tn.z, 0.0f));
    float tFar = min(min(tf.x, tf.y), min(tf.z, tMax)) * kAabbExitScale;
    return tNear <= tFar ? tNear : kInfinity;
}

SHARED_END
#endif
