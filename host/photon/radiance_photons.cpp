#include "photon/radiance_photons.h"

#include <algorithm>

namespace vkp {

RadiancePhotons::RadiancePhotons(vk::Context& context, const PhotonGrid& globalGrid, uint32_t photonCount,
                                 float photonPower, uint32_t stride, uint32_t k, float maxRadius)
    : m_count(photonCount),  // a slot per photon: radiance photons where the shader picks them
      m_photons(context, "radiance photons", sizeof(gpu::GpuPhoton), std::max(1u, m_count),
                globalGrid.photonArray().segmentShift()),
      m_kernel(context) {
    m_params.grid = globalGrid.view(photonPower);
    m_params.photonCount = photonCount;
    m_params.stride = std::max(1u, stride);
    m_params.k = k;
    m_params.maxRadius = maxRadius;
    m_kernel.bind(gpu::kRadiancePhotonsGridBinding, globalGrid.cellStart());
    m_kernel.bind(gpu::kRadiancePhotonsGridBinding + 1, globalGrid.photons());
    m_photons.reserve(std::max(1u, m_count));
    m_kernel.bind(gpu::kRadiancePhotonsOutputBinding, m_photons.table());
    PhotonGridSettings settings = globalGrid.settings();
    settings.requiredFlags = 0;
    settings.rejectedFlags = 0;
    m_grid = std::make_unique<PhotonGrid>(context, m_photons, std::max(1u, m_count), settings, m_photons.segmentShift());
}

void RadiancePhotons::record(VkCommandBuffer cmd) const {
    m_kernel.record(cmd, m_count, m_params);
    vk::computeBarrier(cmd);
    m_grid->record(cmd);
}

}  // namespace vkp
