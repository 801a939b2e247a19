// The guiding cache refined by the guided path tracer's own samples (--guide-learn on,
// docs/guided-path-tracing.md): the photons give each cache grid its first distribution; the
// learning path tracer (guided_learning_pathtrace.comp) adds the incident radiance its guided
// vertices sample to their grids' direction cells, and before samples 8, 16, 32, ... (every
// doubling) guide_learn_update.comp turns the sums into the CDFs the next samples draw from,
// blended with the photons' by how many samples each grid has learned. Every sample is unbiased
// for the distribution it was drawn from, so all of them count towards the image.
#pragma once

#include <cstdint>

#include "photon/guide_cache.h"
#include "shared/kernels/guide_learn.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class GuideLearning {
public:
    // Keeps a copy of the cache's photon CDFs (submits and waits). `meanRadiance`: the scene's
    // mean radiance (emitted power / (pi * surface area)), the unit of the sums' fixed point.
    GuideLearning(vk::Context& context, const GuideCache& cache, double meanRadiance);

    // The first sample index of each learning iteration after the first: 8, 16, 32, ...
    static bool iterationStartsAt(uint32_t sample);
    // The first iteration start after `sample`.
    static uint32_t nextIterationStart(uint32_t sample);

    // Before sample `sample` of a render: at 0 restores the photons' CDFs and clears the sums; at
    // an iteration's start updates the CDFs from the sums; else nothing. Barriers included.
    void recordBefore(VkCommandBuffer cmd, uint32_t sample) const;

    // The sums the learning path tracer adds to (kPathTraceGuideLearnBinding).
    const vk::Buffer& sums() const { return m_sums; }
    uint64_t bytes() const { return m_prior.size() + m_sums.size(); }

private:
    void record(VkCommandBuffer cmd, bool reset) const;

    uint32_t m_gridCount;
    uint32_t m_gridSize;
    float m_scale;
    vk::Buffer m_prior;
    vk::Buffer m_sums;
    vk::Kernel<gpu::GuideLearnUpdateKernel> m_update;
};

}  // namespace vkp
