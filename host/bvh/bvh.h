// Bounding volume hierarchy over triangles: binned SAH build on the host (Wald, "On fast
// Construction of SAH-based Bounding Volume Hierarchies", 2007), flattened into 32-byte nodes with
// adjacent children, root at index 0. The GPU walks it in shaders/shared/bvh_traverse.glsl.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scene/scene.h"
#include "shared/gpu_types.glsl"

namespace vkp {

struct Bvh {
    std::vector<gpu::GpuBvhNode> nodes;
    // The build reorders triangles: position i of the GPU triangle arrays holds the input
    // triangle triangleOrder[i].
    std::vector<uint32_t> triangleOrder;
    uint32_t depth = 0;
};

// Deterministic; handles empty input (a single empty leaf) and coincident centroids.
Bvh buildBvh(std::span<const Triangle> triangles);

// Triangles in BVH order, in the GPU layout.
std::vector<gpu::GpuTriangle> gpuTriangles(std::span<const Triangle> triangles, const Bvh& bvh);

struct RayHit {
    bool hit = false;
    float t = 0.0f;
    uint32_t triangle = 0;  // index in BVH order
    float b1 = 0.0f;
    float b2 = 0.0f;
};

// CPU closest hit with the same shared intersection code as the GPU (tests and tools).
RayHit closestHit(const Bvh& bvh, std::span<const gpu::GpuTriangle> triangles, glm::vec3 org, glm::vec3 dir,
                  float tMax);

// SAH cost of a built tree (traversal 1, intersection 1), for comparing builds.
double sahCost(const Bvh& bvh);

}  // namespace vkp
