// Traces photon paths on the GPU into one photon buffer (caustic, global and primary photons
// together, told apart by their flags) and reads back the counters.
#pragma once

#include <cstdint>
#include <vector>

#include "passes/scene_buffers.h"
#include "shared/photon.glsl"
#include "vk/buffer.h"

namespace vkp {

struct PhotonSettings {
    uint32_t paths = 100000;      // photon paths emitted (Halton indices firstPath ...)
    uint32_t firstPath = 0;       // progressive passes use fresh Halton ranges
    uint32_t maxDeposits = 8;     // stored photons per path at most
    uint32_t seed = 0;
};

struct PhotonCounters {
    uint64_t emitted = 0;
    uint64_t storedCaustic = 0;
    uint64_t storedGlobal = 0;
    uint64_t storedPrimary = 0;
    uint64_t absorbed = 0;
    uint64_t lost = 0;
    uint64_t truncated = 0;
};

class PhotonTracer {
public:
    PhotonTracer(vk::Context& context, const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers);

    // Traces `settings.paths` paths; the photon buffer holds paths * maxDeposits slots (empty
    // slots have no kPhotonValid flag). Refuses (InputError) a buffer beyond the device's
    // storage-buffer range.
    PhotonCounters trace(const PhotonSettings& settings);

    const vk::Buffer& photons() const { return m_photons; }
    // Watts carried by a photon of relative power 1: total light power / paths.
    double nominalPhotonPower() const { return m_nominalPower; }
    std::vector<gpu::GpuPhoton> downloadPhotons() const { return m_photons.download<gpu::GpuPhoton>(); }

private:
    vk::Context& m_context;
    const SceneBuffers& m_buffers;
    glm::vec3 m_sceneCenter;
    float m_sceneRadius;
    double m_totalPower;
    vk::Buffer m_photons;
    vk::Buffer m_counters;
    double m_nominalPower = 0.0;
};

}  // namespace vkp
