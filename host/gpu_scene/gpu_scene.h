// The scene as integrators see it: the loaded scene, its arrays in GPU layout (BVH built) and
// their upload to one device, made once and shared by every render of the scene.
#pragma once

#include <span>

#include "gpu_scene/scene_buffers.h"
#include "scene/scene.h"

namespace vkp {
namespace vk { class Context; }

class GpuScene {
public:
    // Builds the BVH and uploads the scene; `scene` must outlive this object. `lightSampling`:
    // how next-event estimation chooses and samples lights (--light-sampler). Textures the
    // device cannot hold are downscaled, with a warning on stderr each (texture_atlas.h).
    GpuScene(vk::Context& context, const Scene& scene, LightSampling lightSampling = {});
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    vk::Context& context() const { return m_context; }
    const Scene& scene() const { return m_scene; }
    const SceneArrays& arrays() const { return m_arrays; }
    const SceneBuffers& buffers() const { return m_buffers; }
    double uploadSeconds() const { return m_uploadSeconds; }
    // Replaces the light-selection data (SceneArrays::lightCdf): --light-sampler photon's cells
    // (lights/light_cells.h). In the same buffer when it fits (returns true); else in a new one
    // (returns false: kernels that bound the scene before must bind it again).
    bool replaceLightSelection(std::vector<float> data);
    // Per-frame rigid motion (docs/bvh.md): new object-to-world transforms of Scene::instances
    // (same order, one each). Rebuilds (or refits) only the top level and uploads only it and the
    // instances; the static tree, the meshes' trees and every other buffer stay. Call between
    // frames, with no kernel using the scene in flight. Scene::instances keeps the load-time
    // transforms; arrays().topLevel holds the current ones. arrays().bvhBuildSeconds and
    // uploadSeconds() then time this update.
    void updateInstanceTransforms(std::span<const glm::mat4> transforms,
                                  TopLevelUpdate mode = TopLevelUpdate::Rebuild);

    // Per-frame motion of punctual lights: Scene::lights (same count, types, intensities and cones
    // as at the build; positions and directions may change) into the light buffer, the light
    // tree rebuilt over them and uploaded in place. Returns false, changing nothing, when the
    // lights differ in more than position and direction (the caller rebuilds the GpuScene).
    bool updatePunctualLights(const Scene& scene);

private:
    vk::Context& m_context;
    const Scene& m_scene;
    SceneArrays m_arrays;
    double m_uploadSeconds = 0.0;  // set while m_buffers is built: declared before it
    SceneBuffers m_buffers;
};

}  // namespace vkp
