#include "bvh/scene_bvh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>

namespace vkp {
namespace {

void appendPositions(std::span<const Triangle> triangles, const Bvh& tree, std::vector<gpu::GpuTriangle>& out) {
    const std::vector<gpu::GpuTriangle> positions = gpuTriangles(triangles, tree);
    out.insert(out.end(), positions.begin(), positions.end());
}

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// The GPU form of one instance: both matrices as rows of 3x4 (inverse in double), flags.
void setTransform(gpu::GpuInstance& g, const glm::mat4& transform, size_t index) {
    const glm::dmat4 m(transform);
    const double det = glm::determinant(glm::dmat3(m));
    if (!finite(m) || !(std::abs(det) > 0.0) || !std::isfinite(det))
        throw std::invalid_argument("instance " + std::to_string(index) + ": the transform is singular or not finite");
    const glm::dmat4 inverse = glm::inverse(m);
    if (!finite(inverse))
        throw std::invalid_argument("instance " + std::to_string(index) + ": the transform's inverse is not finite");
    for (int r = 0; r < 3; ++r) {
        g.objectToWorld[r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
        g.worldToObject[r] = glm::vec4(inverse[0][r], inverse[1][r], inverse[2][r], inverse[3][r]);
    }
    g.flags = det < 0.0 ? gpu::kInstanceMirrored : 0u;
}

// World bounds of an instance: its mesh's object-space box with the eight corners transformed.
Bounds worldBounds(const Bounds& object, const glm::mat4& transform) {
    Bounds b;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? object.max.x : object.min.x, (corner & 2) ? object.max.y : object.min.y,
                          (corner & 4) ? object.max.z : object.min.z);
        b.grow(glm::vec3(transform * glm::vec4(p, 1.0f)));
    }
    return b;
}

std::vector<Bounds> instanceBounds(const InstanceLevel& top, std::span<const glm::mat4> transforms) {
    std::vector<Bounds> bounds(transforms.size());
    for (size_t i = 0; i < transforms.size(); ++i)
        bounds[i] = worldBounds(top.meshBounds[top.instanceMesh[i]], transforms[i]);
    return bounds;
}

// Builds the top level over `bounds` into bvh.nodes from header.tlasRoot on (one instance per
// leaf: count kBvhInstanceLeaf, leftOrFirst the instance).
void buildTopLevel(std::vector<gpu::GpuBvhNode>& nodes, InstanceLevel& top, const std::vector<Bounds>& bounds) {
    BvhBuildOptions options;
    options.maxLeafSize = 1;
    options.maxDepth = kTopLevelMaxDepth;
    const Bvh tree = buildBvh(std::span<const Bounds>(bounds), options);
    const uint32_t base = top.header.tlasRoot;
    if (nodes.size() != base + tree.nodes.size()) nodes.resize(base + tree.nodes.size());
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        gpu::GpuBvhNode n = tree.nodes[i];
        if (n.count > 0) {
            n.leftOrFirst = tree.triangleOrder[n.leftOrFirst];
            n.count = gpu::kBvhInstanceLeaf;
        } else {
            n.leftOrFirst += base;
        }
        nodes[base + i] = n;
    }
    top.depth = tree.depth;
}

// Same topology, new boxes: children follow their parent in the array, so one backward sweep
// sees every child before its parent.
void refitTopLevel(std::vector<gpu::GpuBvhNode>& nodes, const InstanceLevel& top, const std::vector<Bounds>& bounds) {
    const uint32_t base = top.header.tlasRoot;
    for (size_t i = nodes.size(); i-- > base;) {
        gpu::GpuBvhNode& n = nodes[i];
        Bounds b;
        if (n.count == gpu::kBvhInstanceLeaf) {
            b = bounds[n.leftOrFirst];
            n.boundsMin = padBoxMin(b.min);
            n.boundsMax = padBoxMax(b.max);
        } else {
            const gpu::GpuBvhNode& l = nodes[n.leftOrFirst];
            const gpu::GpuBvhNode& r = nodes[n.leftOrFirst + 1];
            n.boundsMin = glm::min(l.boundsMin, r.boundsMin);
            n.boundsMax = glm::max(l.boundsMax, r.boundsMax);
        }
    }
}

}  // namespace

float rayOffsetScale(const Bounds& bounds) {
    if (bounds.empty()) return 1.0f;
    const glm::vec3 reach = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
    const float r = std::max(reach.x, std::max(reach.y, reach.z));
    return r > 0.0f ? r : 1.0f;
}

SceneBvh buildSceneBvh(const Scene& scene) {
    SceneBvh bvh;
    const Bvh staticTree = buildBvh(scene.triangles);
    bvh.nodes = staticTree.nodes;
    bvh.staticDepth = staticTree.depth;
    bvh.staticOrder = staticTree.triangleOrder;
    appendPositions(scene.triangles, staticTree, bvh.triangles);
    InstanceLevel& top = bvh.top;
    top.header.staticTriangles = static_cast<uint32_t>(bvh.triangles.size());
    top.header.rayOffsetScale = rayOffsetScale(scene.bounds);
    if (scene.instances.empty()) return bvh;
    if (scene.instances.size() > kMaxInstances)
        throw std::length_error("more than " + std::to_string(kMaxInstances) + " instances");

    // Only meshes some instance uses get a tree (and triangles on the device).
    std::vector<bool> used(scene.meshes.size(), false);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const uint32_t mesh = scene.instances[i].mesh;
        if (mesh >= scene.meshes.size() || scene.meshes[mesh].triangles.empty())
            throw std::invalid_argument("instance " + std::to_string(i) + ": mesh " + std::to_string(mesh) +
                                        " does not exist or has no triangles");
        used[mesh] = true;
    }
    BvhBuildOptions meshOptions;
    meshOptions.maxDepth = kMeshBvhMaxDepth;
    bvh.meshFirstTriangle.assign(scene.meshes.size(), 0);
    bvh.meshRoot.assign(scene.meshes.size(), 0);
    bvh.meshOrder.resize(scene.meshes.size());
    top.meshBounds.resize(scene.meshes.size());
    top.meshTriangles.assign(scene.meshes.size(), 0);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        if (!used[m]) continue;
        const Mesh& mesh = scene.meshes[m];
        const Bvh tree = buildBvh(mesh.triangles, meshOptions);
        const auto nodeBase = static_cast<uint32_t>(bvh.nodes.size());
        const auto triangleBase = static_cast<uint32_t>(bvh.triangles.size());
        for (gpu::GpuBvhNode n : tree.nodes) {
            n.leftOrFirst += n.count > 0 ? triangleBase : nodeBase;
            bvh.nodes.push_back(n);
        }
        bvh.meshRoot[m] = nodeBase;
        bvh.meshFirstTriangle[m] = triangleBase;
        bvh.meshOrder[m] = tree.triangleOrder;
        top.meshTriangles[m] = static_cast<uint32_t>(mesh.triangles.size());
        for (const Triangle& t : mesh.triangles)
            for (const glm::vec3& p : t.p) top.meshBounds[m].grow(p);
        appendPositions(mesh.triangles, tree, bvh.triangles);
    }

    uint64_t nextId = top.header.staticTriangles;
    top.instances.resize(scene.instances.size());
    std::vector<glm::mat4> transforms;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        gpu::GpuInstance& g = top.instances[i];
        g.blasRoot = bvh.meshRoot[instance.mesh];
        g.firstTriangle = bvh.meshFirstTriangle[instance.mesh];
        g.firstId = static_cast<uint32_t>(nextId);
        nextId += scene.meshes[instance.mesh].triangles.size();
        if (nextId >= gpu::kBvhNoTriangle)
            throw std::length_error("the instances hold more than 2^32 - 2 triangles in all (hit ids are 32-bit)");
        transforms.push_back(instance.transform);
        top.instanceMesh.push_back(instance.mesh);
    }
    top.header.instanceCount = static_cast<uint32_t>(scene.instances.size());
    top.header.tlasRoot = static_cast<uint32_t>(bvh.nodes.size());
    updateInstances(bvh.nodes, top, transforms, TopLevelUpdate::Rebuild);
    return bvh;
}

void updateInstances(std::vector<gpu::GpuBvhNode>& nodes, InstanceLevel& top, std::span<const glm::mat4> transforms,
                     TopLevelUpdate mode) {
    if (transforms.size() != top.instances.size())
        throw std::invalid_argument("updateInstances: " + std::to_string(transforms.size()) + " transforms for " +
                                    std::to_string(top.instances.size()) + " instances");
    if (top.instances.empty()) return;
    for (size_t i = 0; i < transforms.size(); ++i) setTransform(top.instances[i], transforms[i], i);
    const std::vector<Bounds> bounds = instanceBounds(top, transforms);
    const bool built = nodes.size() > top.header.tlasRoot;
    if (mode == TopLevelUpdate::Refit && built) refitTopLevel(nodes, top, bounds);
    else buildTopLevel(nodes, top, bounds);
}

namespace {
// The instance a hit id at or above staticTriangles belongs to (instances are in firstId order).
const gpu::GpuInstance& instanceOfHit(const gpu::BvhArrays& arrays, uint32_t hitId) {
    const auto after = std::upper_bound(arrays.instances.begin(), arrays.instances.end(), hitId,
                                        [](uint32_t id, const gpu::GpuInstance& g) { return id < g.firstId; });
    return *(after - 1);
}
}  // namespace

uint32_t triangleOfHit(const gpu::BvhArrays& arrays, uint32_t hitId) {
    if (hitId < arrays.header.staticTriangles) return hitId;
    const gpu::GpuInstance& g = instanceOfHit(arrays, hitId);
    return g.firstTriangle + (hitId - g.firstId);
}

gpu::GpuTriangle worldTriangle(const gpu::BvhArrays& arrays, uint32_t hitId) {
    if (hitId < arrays.header.staticTriangles) return arrays.triangles[hitId];
    const gpu::GpuInstance& g = instanceOfHit(arrays, hitId);
    gpu::GpuTriangle t = arrays.triangles[g.firstTriangle + (hitId - g.firstId)];
    for (glm::vec4* v : {&t.v0, &t.v1, &t.v2})
        *v = glm::vec4(gpu::transformPoint3x4(g.objectToWorld[0], g.objectToWorld[1], g.objectToWorld[2], glm::vec3(*v)),
                       v->w);
    return t;
}

RayHit closestHit(const gpu::BvhArrays& arrays, glm::vec3 org, glm::vec3 dir, float tMax, bool cullBackFaces) {
    RayHit hit;
    hit.t = tMax;
    if (arrays.nodes.empty()) return hit;
    uint32_t id = gpu::kBvhNoTriangle;
    hit.hit = gpu::traceClosest(arrays, org, dir, tMax, cullBackFaces, hit.t, id, hit.b1, hit.b2);
    if (hit.hit) hit.triangle = id;
    return hit;
}

bool anyHit(const gpu::BvhArrays& arrays, glm::vec3 org, glm::vec3 dir, float tMax) {
    return !arrays.nodes.empty() && gpu::traceAny(arrays, org, dir, tMax);
}

}  // namespace vkp
