#include "photon/photon_tracer.h"

#include <fmt/format.h>

#include "util/errors.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {

PhotonTracer::PhotonTracer(vk::Context& context, const Scene& scene, const SceneArrays& arrays,
                           const SceneBuffers& buffers)
    : m_context(context), m_buffers(buffers), m_sceneCenter(scene.bounds.center()),
      m_sceneRadius(std::max(0.5f * glm::length(scene.bounds.extent()), 1e-6f)), m_totalPower(arrays.totalLightPower),
      m_counters(context, "photon counters", gpu::kPhotonCounterCount * sizeof(uint32_t), vk::kStorageUsage) {
    if (!(m_totalPower > 0.0)) throw InputError("the scene's lights emit no power: no photons to trace");
}

void PhotonTracer::ensureCapacity(uint64_t photonBytes, uint64_t listBytes, uint64_t trackBytes) {
    trackBytes = std::max<uint64_t>(trackBytes, sizeof(gpu::GpuPathTrack));
    const bool photonsFit = m_photons && m_photons.size() >= photonBytes;
    const bool listFits = m_pathList && m_pathList.size() >= listBytes;
    const bool tracksFit = m_tracks && m_tracks.size() >= trackBytes;
    if (photonsFit && listFits && tracksFit) return;
    m_pass.reset();  // bound to the old buffers; made again by the next trace
    if (!photonsFit) m_photons = vk::Buffer(m_context, "photon slots", photonBytes, vk::kStorageUsage);
    if (!listFits) m_pathList = vk::Buffer(m_context, "photon path list", std::max<uint64_t>(listBytes, 16), vk::kStorageUsage);
    if (!tracksFit) m_tracks = vk::Buffer(m_context, "photon path tracks", trackBytes, vk::kStorageUsage);
}

void PhotonTracer::reserve(uint32_t paths, uint32_t maxDeposits, bool tracks) {
    // the kernel: at the first trace
    ensureCapacity(uint64_t(paths) * maxDeposits * sizeof(gpu::GpuPhoton), 16, tracks ? uint64_t(paths) * sizeof(gpu::GpuPathTrack) : 0);
}

PhotonCounters PhotonTracer::trace(const PhotonSettings& settings) { return run(settings, settings.paths, false, {}); }

PhotonCounters PhotonTracer::traceList(const PhotonSettings& settings, std::span<const uint32_t> paths,
                                       const std::function<void(VkCommandBuffer)>& after) {
    if (paths.empty()) throw InputError("photon tracing needs at least one path");
    ensureCapacity(16, paths.size_bytes());
    m_pathList.upload(paths.data(), paths.size_bytes());
    return run(settings, static_cast<uint32_t>(paths.size()), true, after);
}

PhotonCounters PhotonTracer::run(const PhotonSettings& settings, uint32_t paths, bool listed,
                                 const std::function<void(VkCommandBuffer)>& after) {
    if (paths == 0 || settings.maxDeposits == 0)
        throw InputError("photon tracing needs at least one path and one deposit per path");
    const uint64_t slots = uint64_t(paths) * settings.maxDeposits;
    ensureCapacity(slots * sizeof(gpu::GpuPhoton), 16, settings.trackPaths ? uint64_t(paths) * sizeof(gpu::GpuPathTrack) : 0);

    gpu::PhotonTraceParams params{};
    params.sceneCenter = m_sceneCenter;
    params.sceneRadius = m_sceneRadius;
    params.firstPath = settings.firstPath;
    params.pathCount = paths;
    params.maxDeposits = settings.maxDeposits;
    params.seed = settings.seed;
    params.pathStride = std::max(settings.pathStride, 1u);
    params.pathList = listed ? 1u : 0u;
    params.requiredFlags = settings.requiredFlags;
    params.trackPaths = settings.trackPaths ? 1u : 0u;
    params.lightCount = m_buffers.lightCount();
    params.totalPower = static_cast<float>(m_totalPower);
    // The kernel is made at the first trace (its pipeline is compiled then): a tracer that never
    // traces (a photon map filled from a selective update's slots) costs no compile.
    if (!m_pass)
        m_pass = std::make_unique<PhotonTracePass>(m_context, m_buffers, m_photons, m_counters, m_pathList, m_tracks);
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        m_photons.fillZero(cmd);
        m_counters.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
        m_pass->record(cmd, params);
        if (after) after(cmd);
        vk::computeToHostBarrier(cmd);
    });
    m_nominalPower = m_totalPower / paths;
    m_slotCount = slots;

    // Read-back (docs/architecture.md): the counters, for the statistics and the map's candidate
    // count (which sets the grid's cell size under deposition).
    const auto c = m_counters.download<uint32_t>();
    PhotonCounters counters;
    counters.emitted = paths;
    counters.storedCaustic = c[gpu::kPhotonCounterStoredCaustic];
    counters.storedGlobal = c[gpu::kPhotonCounterStoredGlobal];
    counters.storedPrimary = c[gpu::kPhotonCounterStoredPrimary];
    counters.absorbed = c[gpu::kPhotonCounterAbsorbed];
    counters.lost = c[gpu::kPhotonCounterLost];
    counters.truncated = c[gpu::kPhotonCounterTruncated];
    counters.sampled = c[gpu::kPhotonCounterSampled];
    return counters;
}

std::vector<gpu::GpuPhoton> PhotonTracer::downloadPhotons() const {
    std::vector<gpu::GpuPhoton> photons(m_slotCount);
    m_photons.download(photons.data(), m_slotCount * sizeof(gpu::GpuPhoton));
    return photons;
}

}  // namespace vkp
