// Which glTF meshes the loader keeps as instanced meshes (scene.h Mesh/Instance, docs/bvh.md)
// instead of flattening every reference to world space, and EXT_mesh_gpu_instancing's
// per-instance transforms.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkp {

inline constexpr const char* kMeshGpuInstancing = "EXT_mesh_gpu_instancing";

// A node's EXT_mesh_gpu_instancing transforms (T * R * S from its TRANSLATION, ROTATION and SCALE
// accessors, each optional, all of one count), in the node's space; empty without the extension.
// Accessors are read bounds-checked (gltf_accessors.h); wrong types, counts that differ, rotations
// that are no unit quaternion and non-finite values are InputErrors naming `element`.
std::vector<glm::dmat4> readMeshInstances(const tinygltf::Model& model, const tinygltf::Node& node,
                                          const std::string& element);

// How many times a node draws its mesh, from the accessors' declared counts alone (no decoding):
// EXT_mesh_gpu_instancing's count, else 1. For the size checks before loading.
uint64_t declaredInstanceCount(const tinygltf::Model& model, const tinygltf::Node& node);

// Per glTF mesh: whether it becomes an instanced mesh. A mesh is instanced when it is drawn at
// least twice in the scene's tree (nodes and EXT_mesh_gpu_instancing instances) and has at least
// `minTriangles` triangles, or when an animation channel moves (translation, rotation, scale) a
// node that draws it or one of its ancestors; never when a primitive's material emits light
// (lights are static triangles, docs/bvh.md), when a skinned node draws it (its vertices are
// placed in world space by the joints) or when the nodes drawing it give different morph weights.
// `everyMesh`: every mesh that can be instanced is, drawn once or not (`vkphoton view`, where
// any node may be moved in place).
std::vector<bool> planInstancedMeshes(const tinygltf::Model& model, const std::vector<int>& roots,
                                      const std::vector<Material>& materials, uint64_t minTriangles,
                                      bool everyMesh = false);

}  // namespace vkp
