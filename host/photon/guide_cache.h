// The guiding cache pass (shaders/guiding/guide_cache_build.comp): a coarse grid over the guiding
// photons and, per bucket and normal bin, the CDF of the photon-flux grid of the bucket's cell, so
// the guided path tracer looks a grid up instead of gathering k photons at every vertex, and the
// grid's indirect irradiance (for guide-driven Russian roulette). The photon integrator's final
// gathers sample the same grids over the global map (photon/, below guiding/, so both reach it).
#pragma once

#include <memory>

#include "photon/photon_grid.h"
#include "shared/guiding.glsl"
#include "shared/kernels/guide_cache.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class GuideCache {
public:
    // A cache over the `slotCount` photon slots of `photons` (e.g. a map's grid photons) with
    // cells of `cellSize` and `tableSize` buckets; `params` gives the grid size (m, n) and, in
    // params.grid.photonPower, the watts of a photon of relative power 1.
    // Photons with any of `rejectedFlags` are left out (a map of every kind: its direct photons).
    GuideCache(vk::Context& context, const vk::SegmentedBuffer& photons, uint32_t slotCount, float cellSize, uint32_t tableSize,
               const gpu::GuideParams& params, uint32_t rejectedFlags = 0);

    // Records the coarse grid and the grids' construction; the caller places barriers around.
    void record(VkCommandBuffer cmd) const;

    const vk::Buffer& cells() const { return m_cells; }
    const vk::Buffer& cdfs() const { return m_cdfs; }
    const vk::Buffer& irradiance() const { return m_irradiance; }
    // The guided path tracer's view of the cache (the coarse grid's cells).
    const gpu::GuideParams& params() const { return m_params; }
    uint64_t bytes() const { return m_cells.size() + m_cdfs.size() + m_irradiance.size(); }

private:
    PhotonGrid m_grid;
    gpu::GuideParams m_params;
    vk::Buffer m_cells;
    vk::Buffer m_cdfs;
    vk::Buffer m_irradiance;
    vk::Kernel<gpu::GuideCacheBuildKernel> m_build;
};

// A cache over the `stored` photons of a built map's grid (photon/photon_map.h) without
// `rejectedFlags` photons, sized for `guidePhotons` of them spread over the scene's `area` with
// `k` photons per grid (params.gridSize, params.grid.photonPower as for the constructor): cells
// kCacheCellFactor times the radius of a disk that holds k of them at that density, about
// 36k/pi photons on a flat cell. Grid noise, not spatial detail, limits the cache
// (docs/benchmarks.md: factors 1.5 to 12 measured). Recorded by the caller.
std::unique_ptr<GuideCache> makeGuideCache(vk::Context& context, const vk::SegmentedBuffer& gridPhotons, uint64_t stored,
                                           uint64_t guidePhotons, uint32_t k, double area, const gpu::GuideParams& params,
                                           uint32_t rejectedFlags);

}  // namespace vkp
