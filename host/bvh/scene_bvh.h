// The scene's two-level BVH in GPU layout (docs/bvh.md): a static tree over Scene::triangles
// (world space, root at node 0, exactly the single-level tree of host/bvh/bvh.h), one bottom-level
// tree per instanced mesh (object space) and a top level over the instances' world bounds, all in
// one node array that shaders/shared/bvh_traverse.glsl walks in one loop. Per-frame motion
// replaces instance transforms and rebuilds or refits only the top level (updateInstances).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/bvh.h"
#include "shared/bvh_traverse.glsl"

namespace vkp {

// Depth limits of the instanced levels: a ray's stack holds a top-level path and a mesh path at
// once, (kTopLevelMaxDepth - 1) + (kMeshBvhMaxDepth - 1) <= kBvhMaxDepth entries. The static tree
// keeps kBvhMaxDepth: while it is walked the stack holds only the top-level root besides.
constexpr uint32_t kTopLevelMaxDepth = 24;
constexpr uint32_t kMeshBvhMaxDepth = 24;
// One instance per top-level leaf, so at most 2^(kTopLevelMaxDepth - 1) instances.
constexpr uint32_t kMaxInstances = 1u << (kTopLevelMaxDepth - 1);

// The instances and what rebuilding the top level over them needs.
struct InstanceLevel {
    std::vector<gpu::GpuInstance> instances;  // Scene::instances order (= firstId order)
    gpu::GpuInstanceHeader header{};
    std::vector<uint32_t> instanceMesh;       // per instance: its Scene::meshes index
    std::vector<Bounds> meshBounds;           // per mesh, object space
    std::vector<uint32_t> meshTriangles;      // per mesh, its triangle count
    uint32_t depth = 0;                       // of the top level
};

struct SceneBvh {
    // Static tree at 0, then each mesh's tree, then the top level (from header.tlasRoot, 2N - 1
    // nodes for N instances, none without instances).
    std::vector<gpu::GpuBvhNode> nodes;
    // Static triangles in world space (BVH order), then each mesh's in object space (BVH order).
    // Positions only: w components zero (host/gpu_scene adds the alpha and light flags).
    std::vector<gpu::GpuTriangle> triangles;
    InstanceLevel top;
    // Where the triangles came from: the static tree's order (index into Scene::triangles per
    // position), and per mesh its first position in `triangles` and its order.
    std::vector<uint32_t> staticOrder;
    std::vector<uint32_t> meshFirstTriangle;
    std::vector<std::vector<uint32_t>> meshOrder;
    std::vector<uint32_t> meshRoot;           // node index of each mesh's root
    uint32_t staticDepth = 0;

    gpu::BvhArrays arrays() const { return {nodes, triangles, top.instances, top.header}; }
};

// The index in the triangle (and shading) arrays of a hit id's triangle.
uint32_t triangleOfHit(const gpu::BvhArrays& arrays, uint32_t hitId);
// World-space vertices of a hit id's triangle (w components as stored).
gpu::GpuTriangle worldTriangle(const gpu::BvhArrays& arrays, uint32_t hitId);

// Throws std::invalid_argument for an instance of a missing or empty mesh or a singular or
// non-finite transform, std::length_error beyond kMaxInstances or 2^32 - 1 hit ids.
SceneBvh buildSceneBvh(const Scene& scene);
// The floor of the shaders' ray offsets (GpuInstanceHeader::rayOffsetScale, scene_access.glsl
// rayEpsilon): the largest |coordinate| of the bounds; 1 for an empty or degenerate box.
float rayOffsetScale(const Bounds& bounds);

enum class TopLevelUpdate {
    Rebuild,  // binned SAH over the new instance bounds (the tree a fresh build makes)
    Refit,    // same topology, boxes recomputed bottom-up (cheaper; quality drops with large motion)
};

// Replaces every instance's object-to-world transform (Scene::instances order, one per instance)
// and updates the top level; the static tree and the meshes' trees are untouched. Only the
// instances and the nodes from top.header.tlasRoot on change (SceneBuffers::updateInstances uploads
// just those).
void updateInstances(std::vector<gpu::GpuBvhNode>& nodes, InstanceLevel& top, std::span<const glm::mat4> transforms,
                     TopLevelUpdate mode = TopLevelUpdate::Rebuild);
inline void updateInstances(SceneBvh& bvh, std::span<const glm::mat4> transforms,
                            TopLevelUpdate mode = TopLevelUpdate::Rebuild) {
    updateInstances(bvh.nodes, bvh.top, transforms, mode);
}

// The shaders' traversal over the two levels on the CPU; RayHit::triangle is the hit id.
// cullBackFaces: a camera ray, which skips the back faces of single-sided opaque triangles
// (traceClosest, docs/scene-format.md "Back faces").
RayHit closestHit(const gpu::BvhArrays& arrays, glm::vec3 org, glm::vec3 dir, float tMax, bool cullBackFaces = false);
bool anyHit(const gpu::BvhArrays& arrays, glm::vec3 org, glm::vec3 dir, float tMax);

}  // namespace vkp
