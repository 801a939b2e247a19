// Bounding volume hierarchy over triangles: binned SAH build on the host (Wald, "On fast
// Construction of SAH-based Bounding Volume Hierarchies", IEEE RT 2007), flattened into 32-byte
// GpuBvhNodes: root at index 0, the two children of an inner node adjacent (leftOrFirst,
// leftOrFirst + 1), leaves (count > 0) holding triangles [leftOrFirst, leftOrFirst + count) of the
// reordered triangle array. The GPU walks it in shaders/shared/bvh_traverse.glsl; closestHit and
// anyHit below run that same code on the CPU (compiled as C++).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scene/scene.h"
#include "shared/bvh_constants.glsl"
#include "shared/gpu_types.glsl"

namespace vkp {

struct BvhBuildOptions {
    enum class Split {
        Sah,     // binned SAH over all three axes (the renderer's choice)
        Median,  // split at the median centroid of the largest axis (baseline for comparisons)
    };
    Split split = Split::Sah;
    // Cost of visiting an inner node (two box tests) relative to one ray/triangle test.
    float traversalCost = 1.0f;
    // Leaves never hold more triangles than this; smaller leaves are made when the SAH prefers
    // them.
    uint32_t maxLeafSize = gpu::kBvhMaxLeafSize;
    // Levels including the root; values above gpu::kBvhMaxDepth (the GPU stack size) are clamped.
    // Where SAH splits would leave too few levels, the build switches to splits by count; only if
    // even a balanced tree cannot fit (more than maxLeafSize * 2^(maxDepth - 1) triangles) do
    // leaves at the last level exceed maxLeafSize.
    uint32_t maxDepth = gpu::kBvhMaxDepth;
};

struct Bvh {
    std::vector<gpu::GpuBvhNode> nodes;
    // The build reorders primitives: position i of the GPU triangle arrays holds the input
    // triangle triangleOrder[i] (a permutation of 0 .. n-1).
    std::vector<uint32_t> triangleOrder;
    uint32_t depth = 0;  // levels, root = 1; at most gpu::kBvhMaxDepth
};

// Deterministic (no threads, no hashing: the same input gives the same tree byte for byte).
// Empty input gives the empty tree: one node with count 0 and leftOrFirst 0, which the
// traversals recognise (an inner node never points at the root). Triangle coordinates must be
// finite; coincident centroids are split in the middle by count.
Bvh buildBvh(std::span<const Triangle> triangles, const BvhBuildOptions& options = {});
// The same over arbitrary primitives given by their bounds.
Bvh buildBvh(std::span<const Bounds> primitiveBounds, const BvhBuildOptions& options = {});

// Triangle positions in BVH order, in the GPU layout.
std::vector<gpu::GpuTriangle> gpuTriangles(std::span<const Triangle> triangles, const Bvh& bvh);

struct RayHit {
    bool hit = false;
    float t = 0.0f;           // tMax on a miss
    uint32_t triangle = 0;    // index in BVH order (into gpuTriangles())
    float b1 = 0.0f;          // barycentrics of v1 and v2
    float b2 = 0.0f;
};

// Closest hit with 0 < t < tMax: traceClosest of shaders/shared/bvh_traverse.glsl on the CPU
// (cullBackFaces: a camera ray, see there).
RayHit closestHit(const Bvh& bvh, std::span<const gpu::GpuTriangle> triangles, glm::vec3 org,
                  glm::vec3 dir, float tMax, bool cullBackFaces = false);
// Any hit with 0 < t < tMax: traceAny of shaders/shared/bvh_traverse.glsl on the CPU.
bool anyHit(const Bvh& bvh, std::span<const gpu::GpuTriangle> triangles, glm::vec3 org,
            glm::vec3 dir, float tMax);

// A node box's padding (bvh.cpp): outward by at least one ulp and 1e-20 per coordinate.
glm::vec3 padBoxMin(glm::vec3 v);
glm::vec3 padBoxMax(glm::vec3 v);

struct BvhStats {
    uint32_t nodeCount = 0;
    uint32_t leafCount = 0;
    uint32_t depth = 0;
    uint32_t maxLeafSize = 0;
    double averageLeafSize = 0.0;
    double sahCost = 0.0;
};

// SAH cost of a built tree (MacDonald and Booth 1990): sum over nodes of area / root area times
// traversalCost (inner) or the triangle count (leaf). Lower is a faster tree for random rays.
double sahCost(const Bvh& bvh, float traversalCost = 1.0f);
BvhStats bvhStats(const Bvh& bvh, float traversalCost = 1.0f);

}  // namespace vkp
