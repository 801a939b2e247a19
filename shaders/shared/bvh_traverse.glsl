// GPU BVH traversal (GLSL only). The including shader declares the buffers
//   readonly buffer BvhNodes { GpuBvhNode bvhNodes[]; };
//   readonly buffer Triangles { GpuTriangle triangles[]; };
// Ordered (near child first) stack traversal; kBvhMaxDepth bounds the stack (the host build
// never exceeds it).
#ifndef VKP_BVH_TRAVERSE_GLSL
#define VKP_BVH_TRAVERSE_GLSL
#ifndef __cplusplus
#include "intersect.glsl"
#include "bvh_constants.glsl"

bool traceClosest(vec3 org, vec3 dir, float tMax, out float tHit, out uint triHit, out float b1Hit,
                  out float b2Hit) {
    vec3 invDir = safeInverseDirection(dir);
    tHit = tMax;
    triHit = 0u;
    b1Hit = 0.0f;
    b2Hit = 0.0f;
    bool found = false;
    GpuBvhNode root = bvhNodes[0];
    if (intersectAabb(org, invDir, root.boundsMin, root.boundsMax, tHit) >= kInfinity) return false;
    uint stack[kBvhMaxDepth];
    uint sp = 0u;
    uint nodeIndex = 0u;
    while (true) {
        GpuBvhNode node = bvhNodes[nodeIndex];
        if (node.count > 0u) {
            for (uint i = node.leftOrFirst; i < node.leftOrFirst + node.count; ++i) {
                GpuTriangle tri = triangles[i];
                float t;
                float b1;
                float b2;
                if (intersectTriangle(org, dir, tri.v0.xyz, tri.v1.xyz, tri.v2.xyz, tHit, t, b1, b2)) {
                    tHit = t;
                    triHit = i;
                    b1Hit = b1;
                    b2Hit = b2;
                    found = true;
                }
            }
        } else {
            uint left = node.leftOrFirst;
            GpuBvhNode l = bvhNodes[left];
            GpuBvhNode r = bvhNodes[left + 1u];
            float dl = intersectAabb(org, invDir, l.boundsMin, l.boundsMax, tHit);
            float dr = intersectAabb(org, invDir, r.boundsMin, r.boundsMax, tHit);
            bool hitL = dl < kInfinity;
            bool hitR = dr < kInfinity;
            if (hitL && hitR) {
                uint nearChild = dl <= dr ? left : left + 1u;
                stack[sp++] = dl <= dr ? left + 1u : left;
                nodeIndex = nearChild;
                continue;
            }
            if (hitL || hitR) {
                nodeIndex = hitL ? left : left + 1u;
                continue;
            }
        }
        if (sp == 0u) break;
        nodeIndex = stack[--sp];
    }
    return found;
}

// Any hit closer than tMax (shadow rays): stops at the first intersection found.
bool traceAny(vec3 org, vec3 dir, float tMax) {
    vec3 invDir = safeInverseDirection(dir);
    GpuBvhNode root = bvhNodes[0];
    if (intersectAabb(org, invDir, root.boundsMin, root.boundsMax, tMax) >= kInfinity) return false;
    uint stack[kBvhMaxDepth];
    uint sp = 0u;
    uint nodeIndex = 0u;
    while (true) {
        GpuBvhNode node = bvhNodes[nodeIndex];
        if (node.count > 0u) {
            for (uint i = node.leftOrFirst; i < node.leftOrFirst + node.count; ++i) {
                GpuTriangle tri = triangles[i];
                float t;
                float b1;
                float b2;
                if (intersectTriangle(org, dir, tri.v0.xyz, tri.v1.xyz, tri.v2.xyz, tMax, t, b1, b2)) return true;
            }
        } else {
            uint left = node.leftOrFirst;
            GpuBvhNode l = bvhNodes[left];
            GpuBvhNode r = bvhNodes[left + 1u];
            bool hitL = intersectAabb(org, invDir, l.boundsMin, l.boundsMax, tMax) < kInfinity;
            bool hitR = intersectAabb(org, invDir, r.boundsMin, r.boundsMax, tMax) < kInfinity;
            if (hitL && hitR) {
                stack[sp++] = left + 1u;
                nodeIndex = left;
                continue;
            }
            if (hitL || hitR) {
                nodeIndex = hitL ? left : left + 1u;
                continue;
            }
        }
        if (sp == 0u) break;
        nodeIndex = stack[--sp];
    }
    return false;
}

#endif
#endif
