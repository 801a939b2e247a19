// The track of one photon path: where its segments went, so that a selective update can tell
// exactly which stored paths a moved object may have changed (host/photon/selective_photon_update.h,
// docs/animation.md "Finding the changed paths"). photon_trace.comp writes one per path when
// PhotonTraceParams.trackPaths is set; selective_mark.comp tests them against the old and new
// bounds of what moved.
//
// A path is the polyline of its ray origins (vertex 0: where it left the light; vertex k: the
// origin of its k-th continuation ray, kRayEpsilon off the k-th hit) ending at its last hit, or,
// for a path that left the scene, a ray from its last origin to infinity. The first
// kPathTrackVertices vertices are kept exactly; the vertices from the last kept one on are
// bounded by a box (a box holds every segment between points inside it), so a long path is
// tested conservatively rather than dropped. If none of its segments (nor its escape ray) meets
// the bounds of what moved, neither before nor after the move, every ray of the path hits what it
// hit before and the path, traced again, is the same bit for bit.
#ifndef VKP_PATH_TRACK_GLSL
#define VKP_PATH_TRACK_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

const uint kPathTrackVertices = 6u;

// Header bits (pathTrackHeader).
const uint kPathTrackCountMask = 0xffu;     // vertices kept (<= kPathTrackVertices)
const uint kPathTrackOverflow = 0x100u;     // more vertices than kept: boxLo/boxHi bound the rest
const uint kPathTrackEscaped = 0x200u;      // the path left the scene along the escape direction

// 128 bytes per path. The w components carry the rest: vertex[0].w the header, vertex[1].w the
// emitting light's index (uint bits), vertex[2..4].w the escape direction.
struct GpuPathTrack {
    vec4 vertex[6];  // kPathTrackVertices
    vec4 boxLo;      // xyz: lower corner of the vertices from vertex[kPathTrackVertices - 1] on (overflow)
    vec4 boxHi;      // xyz: upper corner
};
STATIC_ASSERT_SIZE(GpuPathTrack, 128)

INLINE uint pathTrackHeader(GpuPathTrack t) { return floatBitsToUint(t.vertex[0].w); }
INLINE uint pathTrackLight(GpuPathTrack t) { return floatBitsToUint(t.vertex[1].w); }
INLINE vec3 pathTrackEscape(GpuPathTrack t) { return vec3(t.vertex[2].w, t.vertex[3].w, t.vertex[4].w); }
INLINE vec3 pathTrackVertex(GpuPathTrack t, uint k) {
    return vec3(t.vertex[k].x, t.vertex[k].y, t.vertex[k].z);
}

// Whether the ray o + t d, t in [0, tMax], meets the box [lo, hi] (slab test; a zero component of
// d keeps the ray in its slab or out of it entirely). Boundaries count as inside.
INLINE bool rayMeetsBox(vec3 o, vec3 d, float tMax, vec3 lo, vec3 hi) {
    float t0 = 0.0f;
    float t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        if (abs(d[a]) < 1.0e-30f) {
            if (o[a] < lo[a] || o[a] > hi[a]) return false;
        } else {
            float inv = 1.0f / d[a];
            float ta = (lo[a] - o[a]) * inv;
            float tb = (hi[a] - o[a]) * inv;
            t0 = max(t0, min(ta, tb));
            t1 = min(t1, max(ta, tb));
        }
    }
    return t0 <= t1;
}

INLINE bool boxesOverlap(vec3 aLo, vec3 aHi, vec3 bLo, vec3 bHi) {
    return aLo.x <= bHi.x && bLo.x <= aHi.x && aLo.y <= bHi.y && bLo.y <= aHi.y && aLo.z <= bHi.z &&
           bLo.z <= aHi.z;
}

// Whether any segment of the track (or its escape ray) meets the box [lo, hi]. The caller
// widens the box by the ray offsets (docs/animation.md).
INLINE bool pathTrackMeetsBox(GpuPathTrack t, vec3 lo, vec3 hi) {
    uint header = pathTrackHeader(t);
    uint count = min(header & kPathTrackCountMask, kPathTrackVertices);
    if (count == 0u) return false;
    for (uint k = 0u; k + 1u < count; ++k) {
        vec3 a = pathTrackVertex(t, k);
        vec3 b = pathTrackVertex(t, k + 1u);
        if (rayMeetsBox(a, b - a, 1.0f, lo, hi)) return true;
    }
    bool overflow = (header & kPathTrackOverflow) != 0u;
    vec3 boxLo = vec3(t.boxLo.x, t.boxLo.y, t.boxLo.z);
    vec3 boxHi = vec3(t.boxHi.x, t.boxHi.y, t.boxHi.z);
    if (overflow && boxesOverlap(boxLo, boxHi, lo, hi)) return true;
    if ((header & kPathTrackEscaped) != 0u) {
        vec3 d = pathTrackEscape(t);
        if (!overflow) return rayMeetsBox(pathTrackVertex(t, count - 1u), d, kInfinity, lo, hi);
        // The escape ray starts somewhere in the overflow box: the box swept along d meets [lo, hi]
        // when the ray from the box's centre meets [lo, hi] grown by the box's half extent.
        vec3 halfExtent = 0.5f * (boxHi - boxLo);
        return rayMeetsBox(0.5f * (boxLo + boxHi), d, kInfinity, lo - halfExtent, hi + halfExtent);
    }
    return false;
}

SHARED_END
#endif
