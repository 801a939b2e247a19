// What changed between two frames of an animation, as a selective photon update needs to know it
// (photon/selective_photon_update.h, docs/animation.md "Finding the changed paths"): the regions
// a moved instance occupied before and occupies now, the lights that moved, and whether anything
// else changed that no region bounds (then every stored path is suspect).
#pragma once

#include <cstdint>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "scene/scene.h"

namespace vkp {

// The parts of a frame's scene that move in place (animation/frame_scene.h), and a hash of the rest.
struct SceneSnapshot {
    std::vector<uint32_t> instanceMeshes;
    std::vector<glm::mat4> instanceTransforms;
    std::vector<Bounds> meshBounds;        // object space, per mesh
    std::vector<gpu::GpuLight> lights;     // as the photon tracer reads them
    uint64_t generation = 0;               // the frames loop's scene generation (rebuilds)
    uint64_t staticHash = 0;               // triangles, shading, materials, textures, light CDF, power (per generation)
    float extent = 1.0f;                   // largest absolute coordinate of the scene's bounds (at least 1)
};

struct SceneChanges {
    std::vector<Bounds> regions;   // world bounds, widened by the ray offsets (regionMargin)
    std::vector<uint32_t> lights;  // indices of lights whose GpuLight changed
    bool unknown = false;          // something no region bounds changed: every path may have changed
    bool any() const { return unknown || !regions.empty() || !lights.empty(); }
};

// `previous` (may be null) lends its static hash when the generation is the same: pass it only for
// the same scene moved in place (instances, lights and cameras), so the hash is computed once per
// scene.
SceneSnapshot snapshotScene(const Scene& scene, const SceneArrays& arrays, uint64_t generation,
                            const SceneSnapshot* previous = nullptr);
SceneChanges sceneChanges(const SceneSnapshot& before, const SceneSnapshot& after);

// The world bounds of an object-space box under an affine transform (its eight corners).
Bounds transformedBounds(const Bounds& object, const glm::mat4& transform);
// How far a path's recorded polyline may lie from its rays (ray origins sit rayEpsilon, at most
// 1e-4 * max(1, |p|), off the surfaces; shaders/render/scene_access.glsl), with room for rounding: the
// regions are widened by this.
float regionMargin(float extent);
// At most `count` regions: neighbours (sorted along the axis the centres spread most) joined into
// unions that bound them.
std::vector<Bounds> mergeRegions(std::vector<Bounds> regions, size_t count);

}  // namespace vkp
