// Radiance photons (Christensen 1999, "Faster photon map global illumination"): the pass
// radiance_photons.comp reads the global map's grid and writes about every stride-th photon
// (chosen by a hash of its own record: radiancePhotonChosen), the first of every bucket and every
// photon of a sparse bucket, with the irradiance of its k nearest photons; a grid over them
// serves final gather rays with one nearest-neighbour lookup instead of a k-nearest estimate per
// ray.
#pragma once

#include <memory>

#include "photon/photon_grid.h"
#include "shared/photon.glsl"
#include "shared/kernels/photon_estimates.glsl"
#include "shared/photon_render.glsl"
#include "vk/buffer.h"
#include "vk/segmented_buffer.h"
#include "vk/kernel.h"

namespace vkp {

class RadiancePhotons {
public:
    // Radiance photons for the `photonCount` photons of `globalGrid` (built, with the watts of a
    // relative power of 1 in `photonPower`).
    RadiancePhotons(vk::Context& context, const PhotonGrid& globalGrid, uint32_t photonCount, float photonPower,
                    uint32_t stride, uint32_t k, float maxRadius);

    // Records the estimates and the grid over them; the caller places barriers around.
    void record(VkCommandBuffer cmd) const;

    const PhotonGrid& grid() const { return *m_grid; }
    uint32_t count() const { return m_count; }  // slots (one per global photon; empty ones are not radiance photons)
    uint64_t bytes() const { return m_photons.bytes() + m_grid->bytes(); }

private:
    gpu::RadiancePhotonParams m_params{};
    uint32_t m_count;
    vk::SegmentedBuffer m_photons;
    vk::Kernel<gpu::RadiancePhotonsKernel> m_kernel;
    std::unique_ptr<PhotonGrid> m_grid;
};

}  // namespace vkp
