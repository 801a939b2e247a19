#include "view/node_picking.h"

#include <algorithm>

#include "bvh/scene_bvh.h"

namespace vkp {
namespace {

// The node of the instance hit id `hitId` belongs to, or -1 for a static triangle.
int nodeOfHit(const Scene& scene, const gpu::BvhArrays& arrays, uint32_t hitId) {
    if (hitId < arrays.header.staticTriangles || arrays.instances.empty()) return -1;
    const auto after = std::upper_bound(arrays.instances.begin(), arrays.instances.end(), hitId,
                                        [](uint32_t id, const gpu::GpuInstance& g) { return id < g.firstId; });
    const size_t instance = size_t(after - arrays.instances.begin()) - 1;  // Scene::instances order
    return instance < scene.instances.size() ? scene.instances[instance].node : -1;
}

int nodeAt(const Scene& scene, const gpu::BvhArrays& arrays, const gpu::GpuCamera& camera, uint32_t width,
           uint32_t height, glm::vec2 pixel) {
    const glm::vec3 org = gpu::cameraRayOrigin(camera, width, height, pixel);
    const glm::vec3 dir = gpu::cameraRayDirection(camera, width, height, pixel);
    const RayHit hit = closestHit(arrays, org, dir, 1e30f, true);
    return hit.hit ? nodeOfHit(scene, arrays, hit.triangle) : -1;
}

}  // namespace

int pickNode(const Scene& scene, const SceneArrays& arrays, const gpu::GpuCamera& camera, uint32_t width,
             uint32_t height, glm::vec2 pixel) {
    return nodeAt(scene, arrays.bvhArrays(), camera, width, height, glm::floor(pixel) + glm::vec2(0.5f));
}

std::vector<uint8_t> nodeMask(const Scene& scene, const SceneArrays& arrays, const gpu::GpuCamera& camera,
                              uint32_t width, uint32_t height, int node) {
    std::vector<uint8_t> mask(size_t(width) * height, 0);
    if (node < 0) return mask;
    const gpu::BvhArrays bvh = arrays.bvhArrays();
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            mask[size_t(y) * width + x] = nodeAt(scene, bvh, camera, width, height, glm::vec2(x + 0.5f, y + 0.5f)) == node;
    return mask;
}

bool nodeCentre(const Scene& scene, int node, glm::vec3& centre) {
    Bounds bounds;
    for (const Instance& instance : scene.instances) {
        if (instance.node != node || instance.mesh >= scene.meshes.size()) continue;
        const Bounds& b = scene.meshes[instance.mesh].bounds;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p(corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y, corner & 4 ? b.max.z : b.min.z);
            bounds.grow(glm::vec3(instance.transform * glm::vec4(p, 1.0f)));
        }
    }
    if (bounds.empty()) return false;
    centre = bounds.center();
    return true;
}

}  // namespace vkp
