// Ray/triangle and ray/box tests shared by the GPU traversal and the host BVH.
#ifndef VKP_INTERSECT_GLSL
#define VKP_INTERSECT_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

// Watertight ray/triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): the ray is sheared onto +z of its dominant axis, so the edge
// functions of neighbouring triangles are computed identically on a shared edge and no ray slips
// through. Hits with 0 < t < tMax return t and the barycentrics (b1, b2) of v1 and v2.
INLINE bool intersectTriangle(vec3 org, vec3 dir, vec3 v0, vec3 v1, vec3 v2, float tMax,
                              INOUT(float) tOut, INOUT(float) b1Out, INOUT(float) b2Out) {
    vec3 ad = abs(dir);
    int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (dir[kz] < 0.0f) {
        int tmp = kx;
        kx = ky;
        ky = tmp;
    }
    float sz = 1.0f / dir[kz];
    float sx = dir[kx] * sz;
    float sy = dir[ky] * sz;
    vec3 a = v0 - org;
    vec3 b = v1 - org;
    vec3 c = v2 - org;
    float ax = a[kx] - sx * a[kz];
    float ay = a[ky] - sy * a[kz];
    float bx = b[kx] - sx * b[kz];
    float by = b[ky] - sy * b[kz];
    float cx = c[kx] - sx * c[kz];
    float cy = c[ky] - sy * c[kz];
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    float det = u + v + w;
    if (det == 0.0f) return false;
    float t = u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz]);
    if (det < 0.0f ? (t >= 0.0f || t <= tMax * det) : (t <= 0.0f || t >= tMax * det)) return false;
    float invDet = 1.0f / det;
    tOut = t * invDet;
    b1Out = v * invDet;
    b2Out = w * invDet;
    return true;
}

// 1 / dir with zero components replaced by a tiny signed value, so the slab test never
// computes 0 * inf (NaN).
INLINE vec3 safeInverseDirection(vec3 dir) {
    float e = 1.0e-20f;
    vec3 d = vec3(abs(dir.x) > e ? dir.x : (dir.x >= 0.0f ? e : -e),
                  abs(dir.y) > e ? dir.y : (dir.y >= 0.0f ? e : -e),
                  abs(dir.z) > e ? dir.z : (dir.z >= 0.0f ? e : -e));
    return vec3(1.0f) / d;
}

// Slab test: the entry distance (>= 0) when the ray meets the box before tMax, else kInfinity.
// The exit distance is widened by a few ulps (Ize, "Robust BVH Ray Traversal", JCGT 2013) so
// rounding never culls a box the ray grazes.
INLINE float intersectAabb(vec3 org, vec3 invDir, vec3 bmin, vec3 bmax, float tMax) {
    vec3 t0 = (bmin - org) * invDir;
    vec3 t1 = (bmax - org) * invDir;
    vec3 tn = min(t0, t1);
    vec3 tf = max(t0, t1);
    float tNear = max(max(tn.x, tn.y), max(tn.z, 0.0f));
    float tFar = min(min(tf.x, tf.y), min(tf.z, tMax)) * 1.0000004f;
    return tNear <= tFar ? tNear : kInfinity;
}

SHARED_END
#endif
