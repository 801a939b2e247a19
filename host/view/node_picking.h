// Which glTF node the viewer's cursor is on: the camera ray through a pixel traced on the CPU
// with the shaders' own traversal (bvh/scene_bvh.h closestHit), its hit id mapped to the
// instance and the instance to the node that placed it. Flattened (static) geometry has no node.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_scene/scene_buffers.h"
#include "scene/scene.h"

namespace vkp {

// The node drawn at window pixel `pixel` (its centre: x + 0.5, y + 0.5), or -1 where the ray
// misses or hits flattened geometry.
int pickNode(const Scene& scene, const SceneArrays& arrays, const gpu::GpuCamera& camera, uint32_t width,
             uint32_t height, glm::vec2 pixel);

// Per pixel, 1 where node `node` is what the camera sees first (the highlight's mask).
std::vector<uint8_t> nodeMask(const Scene& scene, const SceneArrays& arrays, const gpu::GpuCamera& camera,
                              uint32_t width, uint32_t height, int node);

// The centre of node `node`'s instances' world bounds (false when it draws none).
bool nodeCentre(const Scene& scene, int node, glm::vec3& centre);

}  // namespace vkp
