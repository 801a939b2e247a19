// The scene of `render --frames` across frames (docs/animation.md "Per frame"): one Renderer
// (GpuScene: BVH, buffers) kept for the whole sequence, so the integrator, its kernels and the
// photon tracer stay too. Each frame's flattened scene moves the instances (top level rebuilt,
// GpuScene::updateInstanceTransforms), punctual lights (light buffer and light tree, in place)
// and cameras; only what cannot be updated in place rebuilds everything (FrameSceneChange::reason).
// With --light-sampler photon, a frame in which something moved traces the light cells (and the
// raster pass's light reach) again in the moved scene.
#pragma once

#include <memory>
#include <string>

#include "render/renderer.h"
#include "scene/scene.h"

namespace vkp {
namespace vk { class Context; }

struct FrameSceneChange {
    bool rebuilt = false;      // a new Renderer: integrators built for the old one must be rebuilt
    std::string reason;        // why it was rebuilt ("first frame", what changed)
    double bvhSeconds = 0.0;   // BVH build, or the top level's rebuild
    double uploadSeconds = 0.0;
    double lightCellSeconds = 0.0;  // --light-sampler photon: the light cells traced again (0: not this frame)
};

class FrameScene {
public:
    // `alwaysRebuild`: rebuild every frame (the way before the in-place update; for benchmarks).
    FrameScene(vk::Context& context, LightSampling lightSampling, bool alwaysRebuild = false);
    ~FrameScene();

    // Makes `next` (the frame's flattened scene) the current one: in place when it differs from
    // the current scene only in instance transforms, punctual lights' positions and directions,
    // and cameras; else (and on the first call) a new Renderer (the previous one is released at
    // the next call, so an integrator built for it can be destroyed after this one returns). The bounds are taken as they are:
    // the frames loop gives every frame the still scene's (they set the photon radius, the
    // directional lights' disk and the grid, which must not depend on the frame).
    FrameSceneChange set(Scene next);

    Renderer& renderer() { return *m_renderer; }
    // Counts the Renderers built so far: a new value means new scene buffers.
    uint64_t generation() const { return m_generation; }
    const Scene& scene() const { return *m_scene; }

    // Why `next` cannot replace `current` in place (empty: it can). Static triangles, meshes,
    // materials, textures, the environment, bounds, the instances' meshes and the lights' kinds
    // and powers must be the same.
    static std::string whyNotInPlace(const Scene& current, const Scene& next);

private:
    vk::Context& m_context;
    LightSampling m_lightSampling;
    bool m_alwaysRebuild;
    std::unique_ptr<Scene> m_scene;        // what m_renderer's GpuScene refers to
    std::unique_ptr<Renderer> m_renderer;
    std::unique_ptr<Renderer> m_retiredRenderer;  // the last rebuild's predecessor, kept one call
    std::unique_ptr<Scene> m_retiredScene;        // (integrators built for it are released after set())
    uint64_t m_generation = 0;
};

}  // namespace vkp
