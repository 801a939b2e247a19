// BVH traversal, one source for the GPU (traceClosest and traceAny in every kernel) and the host
// (closestHit and anyHit in host/bvh/bvh.cpp, which tests/bvh_test.cpp checks against brute force
// over every triangle), so the tests check the shaders' own traversal.
//
// The arrays are reached through BVH_NODE(i) and BVH_TRIANGLE(i):
//  - GLSL: the including shader declares, before including this file,
//      readonly buffer BvhNodes { GpuBvhNode bvhNodes[]; };   // host/bvh: root at 0, children adjacent
//      readonly buffer Triangles { GpuTriangle triangles[]; }; // in BVH order (Bvh::triangleOrder)
//  - C++: every function takes a BvhArrays (spans of the same two arrays) as its first argument
//    (BVH_ARRAYS_PARAM; nothing in GLSL).
//
// Ordered depth-first traversal with a per-invocation stack: at an inner node both child boxes
// are tested, the nearer is visited next and the farther pushed with its entry distance, which is
// re-checked against the closest hit so far when popped. The stack holds at most depth - 1
// entries; the host build never makes a tree deeper than kBvhMaxDepth. A deeper tree overflows it:
// the farther child is then skipped and kTerminationStackOverflow noted; a walk that ends any
// other way than by running out of subtrees (lavapipe's loop budget, kBvhMaxSteps) notes that too
// (shared/terminations.glsl), so the kernel can count the rays cut short.
#ifndef VKP_BVH_TRAVERSE_GLSL
#define VKP_BVH_TRAVERSE_GLSL
#include "compat.glsl"
#include "gpu_types.glsl"
#include "intersect.glsl"
#include "bvh_constants.glsl"
#include "terminations.glsl"
#ifdef __cplusplus
#include <span>
#endif
SHARED_BEGIN

#ifdef __cplusplus
// The tree (Bvh::nodes) and its triangles in BVH order (gpuTriangles()).
struct BvhArrays {
    std::span<const GpuBvhNode> nodes;
    std::span<const GpuTriangle> triangles;
};
#define BVH_ARRAYS_PARAM const BvhArrays& bvhArrays,
#define BVH_ARRAYS_ARG bvhArrays,
#define BVH_NODE(i) bvhArrays.nodes[i]
#define BVH_TRIANGLE(i) bvhArrays.triangles[i]
#else
#define BVH_ARRAYS_PARAM
#define BVH_ARRAYS_ARG
#define BVH_NODE(i) bvhNodes[i]
#define BVH_TRIANGLE(i) triangles[i]
#endif

// Whether a hit on an alpha-tested `triangle` (v0.w != 0, index tri) counts: the including GLSL
// defines it as glTF's alpha test (scene_access.glsl alphaPasses); the host traversal has no
// materials, so every hit counts there. It is evaluated OUTSIDE the traversal's triangle loop, by
// the trace wrappers below (lavapipe inlines it at every trace call site: inside the loop it cost
// every triangle test of every scene, issue 17).
#ifndef BVH_ALPHA_TEST
#define BVH_ALPHA_TEST(triangle, tri, b1, b2, org, dir) true
#endif

// Triangle index reported by traceClosest when nothing is hit.
const uint kBvhNoTriangle = 0xffffffffu;

// Traversals one trace may run: the first, then one per alpha-tested hit that fails the test
// (restarting past it). A ray passing more cut-out layers than that counts as a miss and notes
// kTerminationLoopBound.
const uint kBvhMaxAlphaPasses = 64u;

// A tree over no triangles is a single node with count 0 and leftOrFirst 0: an inner node can
// never point at index 0 (the root), and no box encodes "empty" for the symmetric slab test.
INLINE bool bvhIsEmptyRoot(GpuBvhNode root) {
    return root.count == 0u && root.leftOrFirst == 0u;
}

// Walks the tree for hits with 0 < t < tMax that come after (tMin, minTri) in (t, index) order:
// t > tMin, or t == tMin and index > minTri (tMin 0: every hit; the alpha restarts pass the hit
// that failed). Closest-hit mode (anyHit false) returns the nearest hit: t, the index into
// triangles[] and the barycentrics (b1, b2) of v1 and v2; among hits at exactly equal t the
// first one visited wins. Any-hit mode returns at the first hit found on a triangle without
// alpha test (shadow and visibility rays); hits on alpha-tested ones only set alphaSeen. On a
// miss: false, t = tMax, tri = kBvhNoTriangle.
INLINE bool traverseBvh(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMin, uint minTri, float tMax, bool anyHit,
                        OUT(float) t, OUT(uint) tri, OUT(float) b1, OUT(float) b2, OUT(bool) alphaSeen) {
    alphaSeen = false;
    t = tMax;
    tri = kBvhNoTriangle;
    b1 = 0.0f;
    b2 = 0.0f;
    vec3 invDir = safeInverseDirection(dir);
    GpuBvhNode node = BVH_NODE(0u);
    if (bvhIsEmptyRoot(node) ||
        intersectAabb(org, invDir, node.boundsMin, node.boundsMax, tMax) >= kInfinity) {
        return false;
    }
    uint stackNode[kBvhMaxDepth];
    float stackEntry[kBvhMaxDepth];
    uint sp = 0u;
    bool finished = false;
    uint step = 0u;
    for (; step < kBvhMaxSteps; ++step) {
        if (node.count > 0u) {
            uint end = node.leftOrFirst + node.count;
            for (uint i = node.leftOrFirst; i < end; ++i) {
                GpuTriangle triangle = BVH_TRIANGLE(i);
                float tCandidate;
                float b1Candidate;
                float b2Candidate;
                if (intersectTriangle(org, dir, vec3(triangle.v0), vec3(triangle.v1), vec3(triangle.v2), t,
                                      tCandidate, b1Candidate, b2Candidate) &&
                    (tCandidate > tMin || (tCandidate == tMin && i > minTri))) {
                    if (anyHit && triangle.v0.w != 0.0f) {
                        alphaSeen = true;
                        continue;
                    }
                    t = tCandidate;
                    tri = i;
                    b1 = b1Candidate;
                    b2 = b2Candidate;
                    if (anyHit) return true;
                }
            }
        } else {
            uint left = node.leftOrFirst;
            GpuBvhNode leftNode = BVH_NODE(left);
            GpuBvhNode rightNode = BVH_NODE(left + 1u);
            float entryLeft = intersectAabb(org, invDir, leftNode.boundsMin, leftNode.boundsMax, t);
            float entryRight = intersectAabb(org, invDir, rightNode.boundsMin, rightNode.boundsMax, t);
            bool hitLeft = entryLeft < kInfinity;
            bool hitRight = entryRight < kInfinity;
            if (hitLeft && hitRight) {
                // Near child first (occluders near the origin are the common case for shadow rays
                // too); on equal entry distances the left one (deterministic).
                bool rightFirst = entryRight < entryLeft;
                if (sp < kBvhMaxDepth) {
                    stackNode[sp] = rightFirst ? left : left + 1u;
                    stackEntry[sp] = rightFirst ? entryLeft : entryRight;
                    ++sp;
                } else {
                    noteTermination(kTerminationStackOverflow);
                }
                node = rightFirst ? rightNode : leftNode;
                continue;
            }
            if (hitLeft || hitRight) {
                node = hitLeft ? leftNode : rightNode;
                continue;
            }
        }
        // Pop the nearest pending subtree that can still hold a closer hit; the same bound as
        // intersectAabb(..., t) would apply (exit widened by kAabbExitScale).
        bool popped = false;
        while (sp > 0u && !popped) {
            --sp;
            if (stackEntry[sp] <= t * kAabbExitScale) {
                node = BVH_NODE(stackNode[sp]);
                popped = true;
            }
        }
        if (!popped) {
            finished = true;
            break;
        }
    }
    // Left without finding the stack empty: cut by lavapipe's budget, or by kBvhMaxSteps.
    if (!finished) noteTermination(step >= kBvhMaxSteps ? kTerminationLoopBound : kTerminationLoopLimit);
    return tri != kBvhNoTriangle;
}

// One trace, alpha test outside the traversal: closest-hit mode restarts past an alpha-tested hit
// that fails BVH_ALPHA_TEST; any-hit mode first walks ignoring alpha-tested triangles, and only
// when it found one of them and no opaque occluder goes on as closest-hit with the alpha test
// (scenes without alpha-tested triangles walk once, as before).
INLINE bool traceBvh(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMax, bool anyHit, OUT(float) t, OUT(uint) tri,
                     OUT(float) b1, OUT(float) b2) {
    bool anyMode = anyHit;
    float tMin = 0.0f;
    uint minTri = kBvhNoTriangle;
    for (uint pass = 0u; pass < kBvhMaxAlphaPasses; ++pass) {
        bool alphaSeen;
        bool hit = traverseBvh(BVH_ARRAYS_ARG org, dir, tMin, minTri, tMax, anyMode, t, tri, b1, b2, alphaSeen);
        if (anyMode) {
            if (hit || !alphaSeen) return hit;
            anyMode = false;
            continue;
        }
        if (!hit || BVH_TRIANGLE(tri).v0.w == 0.0f ||
            BVH_ALPHA_TEST(BVH_TRIANGLE(tri), tri, b1, b2, org, dir)) {
            return hit;
        }
        tMin = t;
        minTri = tri;
    }
    noteTermination(kTerminationLoopBound);
    t = tMax;
    tri = kBvhNoTriangle;
    return false;
}

INLINE bool traceClosest(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMax, OUT(float) t, OUT(uint) tri, OUT(float) b1,
                         OUT(float) b2) {
    return traceBvh(BVH_ARRAYS_ARG org, dir, tMax, false, t, tri, b1, b2);
}

INLINE bool traceAny(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMax) {
    float t;
    uint tri;
    float b1;
    float b2;
    return traceBvh(BVH_ARRAYS_ARG org, dir, tMax, true, t, tri, b1, b2);
}

#undef BVH_ARRAYS_PARAM
#undef BVH_ARRAYS_ARG
#undef BVH_NODE
#undef BVH_TRIANGLE

SHARED_END
#endif
