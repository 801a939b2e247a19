// The photon integrator (--integrator photon): Jensen's two-pass method (shared/papers/004) on the
// GPU. Pass 1 traces the global and caustic photon maps (render/photon_map.h). Pass 2, per
// camera sample: visible points behind delta bounces with emission and next-event direct light
// (visible_points.comp), caustics from the caustic map (caustic_estimate.comp), and indirect
// light by a final gather into the global map (final_gather.comp).
//
// With `progressive`, every sample is a pass of stochastic progressive photon mapping (Hachisuka
// & Jensen 2009): fresh photons from a new Halton range, new visible points, and per-pixel radii
// that shrink (sppm_update.comp), so the estimate converges to the path tracer's answer.
#pragma once

#include <atomic>

#include "gpu_scene/scene_buffers.h"
#include "render/renderer.h"

namespace vkp {

class PhotonIntegrator {
public:
    PhotonIntegrator(vk::Context& context, const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers);

    RenderResult render(const RenderSettings& settings, const ProgressCallback& progress,
                        const std::atomic<bool>* stop);

    // The default gather radius: 1.5 % of the scene's bounding radius.
    static float defaultRadius(const Scene& scene);

private:
    RenderResult renderTwoPass(const RenderSettings& settings, float radius, const ProgressCallback& progress,
                               const std::atomic<bool>* stop);
    RenderResult renderProgressive(const RenderSettings& settings, float radius, const ProgressCallback& progress,
                                   const std::atomic<bool>* stop);

    vk::Context& m_context;
    const Scene& m_scene;
    const SceneArrays& m_arrays;
    const SceneBuffers& m_buffers;
};

}  // namespace vkp
