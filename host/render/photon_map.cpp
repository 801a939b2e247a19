#include "render/photon_map.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {
namespace {

constexpr uint64_t kChunkSlots = 1u << 21;  // 64 MiB of photon slots per traced chunk

}  // namespace

double sceneSurfaceArea(const SceneArrays& arrays) {
    double area = 0.0;
    for (const gpu::GpuTriangle& t : arrays.triangles)
        area += 0.5 * glm::length(glm::cross(glm::vec3(t.v1 - t.v0), glm::vec3(t.v2 - t.v0)));
    return std::max(area, 1e-12);
}

float evenSpreadRadius(uint32_t k, uint64_t photons, double area) {
    const double density = std::max<double>(1.0, double(photons)) / area;
    return static_cast<float>(std::sqrt(k / (gpu::kPi * density)));
}

PhotonMap::PhotonMap(vk::Context& context, const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers,
                     const PhotonMapSettings& settings)
    : m_context(context), m_settings(settings), m_tracer(context, scene, arrays, buffers) {
    if (settings.paths == 0 || settings.maxDeposits == 0)
        throw InputError("a photon map needs at least one path and one deposit per path");
    const uint64_t maxPhotons = context.properties().limits.maxStorageBufferRange / sizeof(gpu::GpuPhoton);
    const uint64_t chunk = settings.chunkPaths ? settings.chunkPaths
                                               : std::max<uint64_t>(1, kChunkSlots / settings.maxDeposits);
    m_chunkPaths = static_cast<uint32_t>(std::min<uint64_t>({chunk, settings.paths, maxPhotons / settings.maxDeposits}));
    if (m_chunkPaths == 0)
        throw InputError(fmt::format("--max-deposits {}: one path's slots exceed the device's storage-buffer range",
                                     settings.maxDeposits));
    m_photonPower = static_cast<float>(arrays.totalLightPower / settings.paths);
    m_capacity = static_cast<uint32_t>(std::min<uint64_t>(uint64_t(settings.paths) * settings.maxDeposits, maxPhotons));
    m_map = vk::Buffer(context, "photon map", VkDeviceSize(m_capacity) * sizeof(gpu::GpuPhoton), vk::kStorageUsage);
    m_state = vk::Buffer(context, "photon map state", gpu::kPhotonMapStateSize * sizeof(uint32_t), vk::kStorageUsage);
    PhotonGridSettings grid;
    grid.cellSize = settings.cellSize;
    grid.requiredFlags = settings.requiredFlags;
    grid.rejectedFlags = settings.rejectedFlags;
    m_grid = std::make_unique<PhotonGrid>(context, m_map, m_capacity, grid);
}

PhotonMapStats PhotonMap::build(uint32_t firstPath) {
    PhotonMapStats stats;
    auto start = Clock::now();
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        m_map.fillZero(cmd);
        m_state.fillZero(cmd);
    });
    for (uint32_t done = 0; done < m_settings.paths; done += m_chunkPaths) {
        PhotonSettings chunk;
        chunk.paths = std::min(m_chunkPaths, m_settings.paths - done);
        chunk.firstPath = firstPath + done;
        chunk.maxDeposits = m_settings.maxDeposits;
        chunk.seed = m_settings.seed;
        stats.traced += m_tracer.trace(chunk);
        if (!m_compaction) {  // the first chunk is the largest: the tracer's slots never move after it
            gpu::PhotonCompactParams params{};
            params.capacity = m_capacity;
            params.requiredFlags = m_settings.requiredFlags;
            params.rejectedFlags = m_settings.rejectedFlags;
            m_compaction = std::make_unique<PhotonCompaction>(m_context, m_tracer.photons(),
                                                              m_chunkPaths * m_settings.maxDeposits, m_map, m_state,
                                                              params);
        }
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            vk::transferToComputeBarrier(cmd);  // the map's clearing
            vk::computeBarrier(cmd);            // the chunk's photon slots
            m_compaction->record(cmd, chunk.paths * chunk.maxDeposits);
        });
        stats.chunks += 1;
    }
    uint32_t state[gpu::kPhotonMapStateSize];
    m_state.download(state, sizeof(state));
    stats.stored = state[gpu::kPhotonMapStateCount];
    stats.dropped = state[gpu::kPhotonMapStateDropped];
    stats.traceSeconds = secondsSince(start);

    start = Clock::now();
    if (m_settings.cellSizeFor) m_grid->setCellSize(m_settings.cellSizeFor(stats.stored));
    stats.cellSize = m_grid->settings().cellSize;
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        vk::computeBarrier(cmd);
        m_grid->record(cmd);
        vk::computeToHostBarrier(cmd);
    });
    stats.gridSeconds = secondsSince(start);
    return stats;
}

uint64_t PhotonMap::bytes() const {
    return m_map.size() + m_grid->photons().size() + m_grid->cellStart().size() * 2 + m_tracer.photons().size();
}

std::vector<gpu::GpuPhoton> PhotonMap::downloadPhotons() const {
    uint32_t count = 0;
    m_state.download(&count, sizeof(count), gpu::kPhotonMapStateCount * sizeof(uint32_t));
    std::vector<gpu::GpuPhoton> photons(count);
    m_map.download(photons.data(), count * sizeof(gpu::GpuPhoton));
    return photons;
}

}  // namespace vkp
