// BVH traversal, one source for the GPU (traceClosest and traceAny in every kernel) and the host
// (closestHit and anyHit in host/bvh/bvh.cpp, which tests/bvh/bvh_test.cpp checks against brute force
// over every triangle), so the tests check the shaders' own traversal.
//
// The arrays are reached through BVH_NODE(i), BVH_TRIANGLE(i), BVH_INSTANCE(i) and
// BVH_INSTANCE_HEADER:
//  - GLSL: the including shader declares, before including this file,
//      readonly buffer BvhNodes { GpuBvhNode bvhNodes[]; };   // static tree at 0, meshes', top level
//      readonly buffer Triangles { GpuTriangle triangles[]; }; // static (BVH order), then meshes'
//      readonly buffer Instances { GpuInstanceHeader instanceHeader; GpuInstance instances[]; };
//    A shader that defines BVH_NODE_AT(i) and BVH_TRIANGLE_AT(i) first reads nodes and triangles
//    through them instead (scene_geometry.glsl: the same buffers as uniform texel buffers, which
//    lavapipe reads with vector gathers; docs/bvh.md "Texel-buffer reads").
//  - C++: every function takes a BvhArrays (spans of the same arrays) as its first argument
//    (BVH_ARRAYS_PARAM; nothing in GLSL).
// docs/bvh.md describes the two levels and the hit ids.
//
// Ordered depth-first traversal with a per-invocation stack: at an inner node both child boxes
// are tested, the nearer is visited next and the farther pushed with its entry distance, which is
// re-checked against the closest hit so far when popped. The stack holds at most depth - 1
// entries; the host build never makes a tree deeper than kBvhMaxDepth. A deeper tree overflows it:
// the farther child is then skipped and kTerminationStackOverflow noted; a walk that ends any
// other way than by running out of subtrees (lavapipe's loop budget, kBvhMaxSteps) notes that too
// (shared/termination_record.glsl), so the kernel can count the rays cut short.
#ifndef VKP_BVH_TRAVERSE_GLSL
#define VKP_BVH_TRAVERSE_GLSL
#include "compat.glsl"
#include "gpu_types.glsl"
#include "intersect.glsl"
#include "bvh_constants.glsl"
#include "termination_record.glsl"
#include "kernels/scene.glsl"
#ifdef __cplusplus
#include <span>
#endif
SHARED_BEGIN

#ifdef __cplusplus
// The trees (SceneArrays::nodes: the static tree at 0, meshes' trees, the top level), their
// triangles (static ones in BVH order, then each mesh's) and the instances. A single tree
// (Bvh::nodes, gpuTriangles()) has no instances: header.instanceCount 0.
struct BvhArrays {
    std::span<const GpuBvhNode> nodes;
    std::span<const GpuTriangle> triangles;
    std::span<const GpuInstance> instances = {};
    GpuInstanceHeader header = {};
};
#define BVH_ARRAYS_PARAM const BvhArrays& bvhArrays,
#define BVH_ARRAYS_ARG bvhArrays,
#define BVH_NODE(i) bvhArrays.nodes[i]
#define BVH_TRIANGLE(i) bvhArrays.triangles[i]
#define BVH_INSTANCE(i) bvhArrays.instances[i]
#define BVH_INSTANCE_HEADER bvhArrays.header
#else
#define BVH_ARRAYS_PARAM
#define BVH_ARRAYS_ARG
#ifdef BVH_NODE_AT  // the including shader reads them its own way (scene_geometry.glsl: texel buffers)
#define BVH_NODE(i) BVH_NODE_AT(i)
#define BVH_TRIANGLE(i) BVH_TRIANGLE_AT(i)
#else
#define BVH_NODE(i) bvhNodes[i]
#define BVH_TRIANGLE(i) triangles[i]
#endif
#define BVH_INSTANCE(i) instances[i]
#define BVH_INSTANCE_HEADER instanceHeader
#endif

// Whether a hit on an alpha-tested `triangle` (v0.w == kTriangleAlphaTested, index tri) counts: the including GLSL
// defines it as glTF's alpha test (scene_access.glsl alphaPasses); the host traversal has no
// materials, so every hit counts there. It is evaluated OUTSIDE the traversal's triangle loop, by
// the trace wrappers below (lavapipe inlines it at every trace call site: inside the loop it cost
// every triangle test of every scene).
#ifndef BVH_ALPHA_TEST
#define BVH_ALPHA_TEST(triangle, tri, b1, b2, org, dir) true
#endif

// What the scene lets the traversal leave out: specialization constants of the kernels (set from
// the bound scene, vk::SceneSpecialization; true unless the scene has no instances, or no
// alpha-tested triangle). lavapipe runs both sides of every branch for its whole SIMD group, so
// the instance entry in every step and the alpha test's texture lookup after every trace cost each
// ray even in scenes without them, unless compiled out (docs/bvh.md). The host
// traversal keeps both.
#ifdef __cplusplus
constexpr bool kSceneHasInstances = true;
constexpr bool kSceneHasAlphaTest = true;
#else
layout(constant_id = kSceneHasInstancesId) const bool kSceneHasInstances = true;
layout(constant_id = kSceneHasAlphaTestId) const bool kSceneHasAlphaTest = true;
#endif

// Hit id reported by traceClosest when nothing is hit.
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

// Rows of a 3x4 matrix (GpuInstance) applied to a point and to a direction.
INLINE vec3 transformPoint3x4(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    return vec3(dot(vec3(r0), p) + r0.w, dot(vec3(r1), p) + r1.w, dot(vec3(r2), p) + r2.w);
}
INLINE vec3 transformVector3x4(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
    return vec3(dot(vec3(r0), v), dot(vec3(r1), v), dot(vec3(r2), v));
}

// Walks the scene for hits with 0 < t < tMax that come after (tMin, minTri) in (t, hit id)
// order: t > tMin, or t == tMin and id > minTri (tMin 0: every hit; the alpha restarts pass the
// hit that failed). Closest-hit mode (anyHit false) returns the nearest hit: t, its hit id
// (docs/bvh.md: the triangle's index for the static tree, the instance's firstId + the index
// within its mesh otherwise), the index of its triangle in triangles[] (triIndex) and the
// barycentrics (b1, b2) of v1 and v2, and whether the ray met its back face (backFace: the ray
// runs along the counter-clockwise normal in the triangle's own space, world for the static tree,
// object for a mesh: glTF's front face is the mesh's counter-clockwise side whatever the node's
// determinant); among hits at exactly equal t the first one visited wins.
// Any-hit mode returns at the first hit found on a triangle without alpha test (shadow and
// visibility rays); hits on alpha-tested and backdrop ones (v0.w != 0) only set alphaSeen. On a miss: false, t = tMax,
// tri = kBvhNoTriangle.
//
// Two levels, one walk and one stack: the static tree (world space, root 0) is walked first
// while the top level's root waits at the bottom of the stack. A top-level leaf enters its
// instance: the ray goes to object space (origin and direction through worldToObject, the
// direction not renormalised, so t means the same distance in both spaces and one running t
// serves both levels) and the walk continues at the mesh's root; popping back below the stack
// depth at which the instance was entered restores the world-space ray.
INLINE bool traverseBvh(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMin, uint minTri, float tMax, bool anyHit,
                        OUT(float) t, OUT(uint) tri, OUT(uint) triIndex, OUT(float) b1, OUT(float) b2,
                        OUT(bool) backFace, OUT(bool) alphaSeen) {
    alphaSeen = false;
    backFace = false;
    triIndex = kBvhNoTriangle;
    t = tMax;
    tri = kBvhNoTriangle;
    b1 = 0.0f;
    b2 = 0.0f;
    vec3 worldInvDir = safeInverseDirection(dir);
    uint stackNode[kBvhMaxDepth];
    float stackEntry[kBvhMaxDepth];
    uint sp = 0u;
    GpuInstanceHeader header = BVH_INSTANCE_HEADER;
    if (kSceneHasInstances && header.instanceCount > 0u) {
        GpuBvhNode top = BVH_NODE(header.tlasRoot);
        float entry = intersectAabb(org, worldInvDir, top.boundsMin, top.boundsMax, tMax);
        if (entry < kInfinity) {
            stackNode[0] = header.tlasRoot;
            stackEntry[0] = entry;
            sp = 1u;
        }
    }
    GpuBvhNode node = BVH_NODE(0u);
    // Visit `node` (its box is hit) or, when false, take the next one from the stack.
    bool visit = !bvhIsEmptyRoot(node) &&
                 intersectAabb(org, worldInvDir, node.boundsMin, node.boundsMax, tMax) < kInfinity;
    // The ray in the space of the tree being walked, and what turns a triangle index there into
    // a hit id; instanceDepth: the stack depth at which the current instance was entered.
    vec3 o = org;
    vec3 d = dir;
    vec3 invDir = worldInvDir;
    bool inInstance = false;
    uint instanceDepth = 0u;
    uint idOffset = 0u;
    bool finished = false;
    uint step = 0u;
    // Two nested loops ("while-while", Aila and Laine 2009): the inner one descends through inner
    // nodes (and enters instances) until the node is a leaf or nothing is left; then the leaf's
    // triangles are tested and the next subtree popped. lavapipe runs every branch of a loop body
    // for its whole SIMD group, so in one loop with both branches (as before) every step paid a
    // triangle test and a node pair; here a descent step pays only the node pair.
    // Each ray visits the same nodes in the same order as with one loop.
    for (; step < kBvhMaxSteps; ++step) {
        for (; step < kBvhMaxSteps && visit && (node.count == 0u || node.count == kBvhInstanceLeaf); ++step) {
            if (kSceneHasInstances && node.count == kBvhInstanceLeaf) {
                GpuInstance instance = BVH_INSTANCE(node.leftOrFirst);
                o = transformPoint3x4(instance.worldToObject[0], instance.worldToObject[1], instance.worldToObject[2], org);
                d = transformVector3x4(instance.worldToObject[0], instance.worldToObject[1], instance.worldToObject[2], dir);
                invDir = safeInverseDirection(d);
                inInstance = true;
                instanceDepth = sp;
                idOffset = instance.firstId - instance.firstTriangle;  // modulo 2^32
                node = BVH_NODE(instance.blasRoot);
                continue;
            }
            uint left = node.leftOrFirst;
            GpuBvhNode leftNode = BVH_NODE(left);
            GpuBvhNode rightNode = BVH_NODE(left + 1u);
            float entryLeft = intersectAabb(o, invDir, leftNode.boundsMin, leftNode.boundsMax, t);
            float entryRight = intersectAabb(o, invDir, rightNode.boundsMin, rightNode.boundsMax, t);
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
            } else if (hitLeft || hitRight) {
                node = hitLeft ? leftNode : rightNode;
            } else {
                visit = false;
            }
        }
        if (visit && node.count > 0u && node.count != kBvhInstanceLeaf) {
            uint end = node.leftOrFirst + node.count;
            for (uint i = node.leftOrFirst; i < end; ++i) {
                GpuTriangle triangle = BVH_TRIANGLE(i);
                float tCandidate;
                float b1Candidate;
                float b2Candidate;
                if (intersectTriangle(o, d, vec3(triangle.v0), vec3(triangle.v1), vec3(triangle.v2), t,
                                      tCandidate, b1Candidate, b2Candidate) &&
                    (tCandidate > tMin || (tCandidate == tMin && i + idOffset > minTri))) {
                    if (kSceneHasAlphaTest && anyHit && triangle.v0.w != 0.0f) {
                        alphaSeen = true;
                        continue;
                    }
                    t = tCandidate;
                    tri = i + idOffset;
                    triIndex = i;
                    b1 = b1Candidate;
                    b2 = b2Candidate;
                    if (anyHit) return true;
                    backFace = dot(d, cross(vec3(triangle.v1) - vec3(triangle.v0), vec3(triangle.v2) - vec3(triangle.v0))) > 0.0f;
                }
            }
            visit = false;
        }
        // An inner node still to visit here means the descent was cut (kBvhMaxSteps, or lavapipe's
        // loop budget): it goes on from that node, nothing is popped past it.
        if (visit) continue;
        // Pop the nearest pending subtree that can still hold a closer hit; the same bound as
        // intersectAabb(..., t) would apply (exit widened by kAabbExitScale). Entries below the
        // instance's depth belong to the world-space levels.
        while (sp > 0u && !visit) {
            if (kSceneHasInstances && inInstance && sp == instanceDepth) {
                o = org;
                d = dir;
                invDir = worldInvDir;
                inInstance = false;
                idOffset = 0u;
            }
            --sp;
            if (stackEntry[sp] <= t * kAabbExitScale) {
                node = BVH_NODE(stackNode[sp]);
                visit = true;
            }
        }
        if (!visit) {
            finished = true;
            break;
        }
    }
    // Left without finding the stack empty: cut by lavapipe's budget, or by kBvhMaxSteps.
    if (!finished) noteTermination(step >= kBvhMaxSteps ? kTerminationLoopBound : kTerminationLoopLimit);
    return tri != kBvhNoTriangle;
}

// Whether a closest hit is skipped as a culled back face: camera rays (cullBackFaces) skip the
// back faces of triangles with v2.w != 0 (glTF doubleSided false and not transmissive,
// host/gpu_scene/scene_buffers.cpp; docs/scene-format.md "Back faces").
INLINE bool culledBackFace(bool cullBackFaces, bool backFace, GpuTriangle triangle) {
    return cullBackFaces && backFace && triangle.v2.w != 0.0f;
}

// One trace, alpha test and back-face culling outside the traversal: closest-hit mode restarts
// past a hit that does not count (a failed BVH_ALPHA_TEST, a culled back face, or a backdrop met
// by a ray other than a camera ray); any-hit mode (never culls) first walks ignoring
// alpha-tested and backdrop triangles (v0.w != 0), and only when it found one of them and no
// opaque occluder goes on as closest-hit (scenes without them walk once).
INLINE bool traceBvh(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMax, bool anyHit, bool cullBackFaces, OUT(float) t,
                     OUT(uint) tri, OUT(float) b1, OUT(float) b2) {
    bool anyMode = anyHit;
    float tMin = 0.0f;
    uint minTri = kBvhNoTriangle;
    for (uint pass = 0u; pass < kBvhMaxAlphaPasses; ++pass) {
        bool alphaSeen;
        bool backFace;
        uint triIndex;
        bool hit = traverseBvh(BVH_ARRAYS_ARG org, dir, tMin, minTri, tMax, anyMode, t, tri, triIndex, b1, b2,
                               backFace, alphaSeen);
        if (anyMode) {
            if (hit || !alphaSeen) return hit;
            anyMode = false;
            continue;
        }
        if (!hit) return false;
        // A hit counts unless it is a culled back face, a sky box's triangle (kTriangleBackdrop:
        // camera rays only, docs/environment.md "Sky boxes") met by another ray, or an
        // alpha-tested one where glTF's alpha test fails.
        GpuTriangle triangle = BVH_TRIANGLE(triIndex);
        if (!culledBackFace(cullBackFaces, backFace, triangle) &&
            (!kSceneHasAlphaTest || triangle.v0.w == 0.0f ||
             (triangle.v0.w == kTriangleBackdrop ? cullBackFaces
                                                 : BVH_ALPHA_TEST(triangle, triIndex, b1, b2, org, dir)))) {
            return true;
        }
        tMin = t;
        minTri = tri;
    }
    noteTermination(kTerminationLoopBound);
    t = tMax;
    tri = kBvhNoTriangle;
    return false;
}

// Closest hit; cullBackFaces for camera rays (primary visibility) only.
INLINE bool traceClosest(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMax, bool cullBackFaces, OUT(float) t,
                         OUT(uint) tri, OUT(float) b1, OUT(float) b2) {
    return traceBvh(BVH_ARRAYS_ARG org, dir, tMax, false, cullBackFaces, t, tri, b1, b2);
}

INLINE bool traceAny(BVH_ARRAYS_PARAM vec3 org, vec3 dir, float tMax) {
    float t;
    uint tri;
    float b1;
    float b2;
    return traceBvh(BVH_ARRAYS_ARG org, dir, tMax, true, false, t, tri, b1, b2);
}

#undef BVH_ARRAYS_PARAM
#undef BVH_ARRAYS_ARG
#undef BVH_NODE
#undef BVH_TRIANGLE
#undef BVH_INSTANCE
#undef BVH_INSTANCE_HEADER

SHARED_END
#endif
