#include "photon/photon_map.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "photon/importon_map.h"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {
namespace {

constexpr uint64_t kChunkSlots = 1u << 21;  // 64 MiB of photon slots per traced chunk
// Paths per chunk (outside density control, whose rounds are its chunks): about 2 s on
// lavapipe, so Ctrl-C and --time-limit are honoured that promptly. Chunking does not change the
// map (a path's photons depend on its Halton index only).
constexpr uint64_t kMaxChunkPaths = 1u << 16;
// A build stopped before it began still traces this many paths, so the map is not empty.
constexpr uint32_t kStoppedChunkPaths = 4096;
// Photons a map holds at most: indices stay far from uint overflow (64 GiB of photons).
constexpr uint64_t kMaxMapPhotons = uint64_t(1) << 31;
// Density control's current-density estimates search one cell (one ring of cells).
constexpr float kDensityRadiusCells = 1.0f;

// Deposits of the kinds a map keeps among what the tracer counted.
uint64_t candidateCount(const PhotonCounters& c, uint32_t required, uint32_t rejected) {
    uint64_t n = 0;
    if (gpu::photonSelected(gpu::kPhotonValid | gpu::kPhotonCaustic, required, rejected)) n += c.storedCaustic;
    if (gpu::photonSelected(gpu::kPhotonValid, required, rejected)) n += c.storedGlobal;
    if (gpu::photonSelected(gpu::kPhotonValid | gpu::kPhotonPrimary, required, rejected)) n += c.storedPrimary;
    return n;
}

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
    : m_totalPower(arrays.totalLightPower), m_context(context), m_scene(scene), m_arrays(arrays), m_buffers(buffers), m_settings(settings),
      m_tracer(context, scene, arrays, buffers) {
    if (settings.paths == 0 || settings.maxDeposits == 0)
        throw InputError("a photon map needs at least one path and one deposit per path");
    const DepositSettings& deposit = settings.deposit;
    if (deposit.mode != gpu::kDepositAll) {
        if (!deposit.importons) throw std::logic_error("importance-driven deposition without an importon map");
        if (!(deposit.epsilon > 0.0f && deposit.epsilon <= 1.0f))
            throw InputError(fmt::format("--deposit-epsilon {}: must lie in (0, 1]", deposit.epsilon));
        if (deposit.mode == gpu::kDepositDensity && deposit.rounds == 0)
            throw InputError("--density-rounds must be at least 1");
        if (deposit.mode == gpu::kDepositDensity && !(deposit.densityAccuracy > 0.0f))
            throw InputError(fmt::format("--density-accuracy {}: must be positive", deposit.densityAccuracy));
    }
    // A chunk's slots are one storage buffer; the map, its grid and density control's
    // redistribution sums are segmented arrays that grow with the photons stored, and their
    // kernels dispatch rows of workgroups past 4 M photons. The sums are indexed 3 i + channel in
    // 32 bits (1.4 G photons).
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    const uint64_t maxSlots = limits.maxStorageBufferRange / sizeof(gpu::GpuPhoton);
    uint64_t maxPhotons = kMaxMapPhotons;
    if (deposit.mode == gpu::kDepositDensity) maxPhotons = std::min<uint64_t>(maxPhotons, UINT32_MAX / 3);
    uint64_t chunk = settings.chunkPaths ? settings.chunkPaths
                                         : std::clamp<uint64_t>(kChunkSlots / settings.maxDeposits, 1, kMaxChunkPaths);
    // Density control decides each round against the photons stored by the rounds before.
    if (deposit.mode == gpu::kDepositDensity && !settings.chunkPaths)
        chunk = std::max<uint64_t>(1, kChunkSlots / settings.maxDeposits);
    if (deposit.mode == gpu::kDepositDensity) chunk = std::min<uint64_t>(chunk, (settings.paths + deposit.rounds - 1) / deposit.rounds);
    m_chunkPaths = static_cast<uint32_t>(std::min<uint64_t>({chunk, settings.paths, maxSlots / settings.maxDeposits}));
    if (m_chunkPaths == 0)
        throw InputError(fmt::format("--max-deposits {}: one path's slots exceed the device's storage-buffer range",
                                     settings.maxDeposits));
    m_photonPower = static_cast<float>(arrays.totalLightPower / settings.paths);
    m_capacity = static_cast<uint32_t>(std::min<uint64_t>(uint64_t(settings.paths) * settings.maxDeposits, maxPhotons));
    m_map = vk::SegmentedBuffer(context, "photon map", sizeof(gpu::GpuPhoton), m_capacity, settings.segmentShift);
    m_state = vk::Buffer(context, "photon map state", gpu::kPhotonMapStateSize * sizeof(uint32_t), vk::kStorageUsage);
    PhotonGridSettings grid;
    grid.cellSize = settings.cellSize;
    grid.requiredFlags = settings.requiredFlags;
    grid.rejectedFlags = settings.rejectedFlags;
    // The hash table follows the photons the first build stores (PhotonGrid::fitTable), not the
    // slots: until then it is the smallest. Density control reads the grid between its rounds,
    // so its table is sized for the slots from the start.
    const bool fitTable = settings.fitGridTable && deposit.mode != gpu::kDepositDensity;
    if (fitTable) grid.tableSize = 1;
    m_grid = std::make_unique<PhotonGrid>(context, m_map, m_capacity, grid, settings.segmentShift);
    // A shorter (stopped) chunk must not reallocate the slots the passes below are bound to.
    m_tracer.reserve(m_chunkPaths, settings.maxDeposits);
}

PhotonMap::~PhotonMap() = default;

void PhotonMap::reserve(uint64_t photons) {
    m_map.reserve(photons);
    m_grid->resize(static_cast<uint32_t>(m_map.allocated()));
    if (m_deposit && m_settings.deposit.mode == gpu::kDepositDensity && m_settings.deposit.redistribute)
        m_deposit->reserve(m_map.allocated());
}

gpu::PhotonDepositParams PhotonMap::depositParams(uint32_t firstPath, uint32_t paths, uint32_t round) const {
    const DepositSettings& d = m_settings.deposit;
    gpu::PhotonDepositParams params{};
    params.map = m_grid->view(1.0f);
    params.slotCount = paths * m_settings.maxDeposits;
    params.firstPath = firstPath;
    params.maxDeposits = m_settings.maxDeposits;
    params.seed = m_settings.seed;
    params.mode = d.mode;
    params.round = round;
    params.densityK = d.densityK;
    params.cutoff = d.cutoff ? 1u : 0u;
    params.requiredFlags = m_settings.requiredFlags;
    params.rejectedFlags = m_settings.rejectedFlags;
    params.importanceScale = d.importons->stats().importanceScale;
    params.epsilon = d.epsilon;
    params.densityAccuracy = d.densityAccuracy;
    params.minDensity = d.minDensity;
    params.densityRadius = kDensityRadiusCells * m_grid->settings().cellSize;
    params.densityFloor = d.densityFloor;
    params.redistribute = d.redistribute ? 1u : 0u;
    return params;
}

PhotonMapStats PhotonMap::buildGrid(PhotonMapStats stats, bool deposit) {
    const auto start = Clock::now();
    const double cpuStart = processCpuSeconds();
    if (m_settings.cellSizeFor) m_grid->setCellSize(m_settings.cellSizeFor(deposit ? stats.candidates : stats.stored));
    stats.cellSize = m_grid->settings().cellSize;
    if (!m_gridBuilt && m_settings.fitGridTable && m_settings.deposit.mode != gpu::kDepositDensity)
        m_grid->fitTable(static_cast<uint32_t>(std::min<uint64_t>(stats.stored, UINT32_MAX)));
    m_gridBuilt = true;
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        vk::computeBarrier(cmd);
        m_grid->record(cmd);
        vk::computeToHostBarrier(cmd);
    });
    stats.gridSeconds = secondsSince(start);
    stats.gridCpuSeconds = processCpuSeconds() - cpuStart;
    stats.bytes = bytes();
    return stats;
}

PhotonMapStats PhotonMap::build(uint32_t firstPath) {
    PhotonMapStats stats;
    auto start = Clock::now();
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        m_map.fillZero(cmd);
        m_state.fillZero(cmd);
    });
    const bool deposit = m_settings.deposit.mode != gpu::kDepositAll;
    const bool densityControl = m_settings.deposit.mode == gpu::kDepositDensity;
    const bool redistribute = densityControl && m_settings.deposit.redistribute;
    uint32_t storedSoFar = 0;  // photons in the grid the next round reads
    uint64_t kept = 0;         // photons the chunks so far keep
    uint32_t done = 0;
    for (; done < m_settings.paths; done += m_chunkPaths) {
        PhotonSettings chunk;
        chunk.paths = std::min(m_chunkPaths, m_settings.paths - done);
        if (m_settings.control)
            if (std::string reason = m_settings.control->stopReason(); !reason.empty()) {
                stats.stopReason = std::move(reason);
                if (done > 0) break;
                chunk.paths = std::min(chunk.paths, kStoppedChunkPaths);  // one small chunk: a map, not nothing
            }
        chunk.firstPath = firstPath + done;
        chunk.maxDeposits = m_settings.maxDeposits;
        chunk.seed = m_settings.seed;
        chunk.requiredFlags = m_settings.requiredFlags;
        stats.traced += m_tracer.trace(chunk);
        bool freshDeposit = false;
        if (!m_compaction) {  // the first chunk is the largest: the tracer's slots never move after it
            gpu::PhotonCompactParams params{};
            params.capacity = m_capacity;
            params.requiredFlags = m_settings.requiredFlags;
            params.rejectedFlags = m_settings.rejectedFlags;
            m_compaction = std::make_unique<PhotonCompaction>(m_context, m_tracer.photons(),
                                                              m_chunkPaths * m_settings.maxDeposits, m_map, m_state,
                                                              params);
            if (deposit) {
                m_deposit = std::make_unique<PhotonDeposit>(m_context, m_buffers, m_settings.deposit.importons->table(),
                                                            m_tracer.photons(), m_chunkPaths * m_settings.maxDeposits,
                                                            m_map, *m_grid, m_settings.segmentShift);
                freshDeposit = true;
            }
        }
        // The deposit decision and the count of the photons the map keeps, then room for exactly
        // those (the map's memory follows what it keeps, not what the paths deposited), then the
        // append.
        const uint32_t slotCount = chunk.paths * chunk.maxDeposits;
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            if (freshDeposit) m_deposit->recordClear(cmd);
            vk::transferToComputeBarrier(cmd);  // the map's clearing (and the deposit's)
            vk::computeBarrier(cmd);            // the chunk's photon slots (and the last round's grid)
            if (deposit) {
                m_deposit->record(cmd, m_settings.deposit.importons->lookupParams(m_settings.requiredFlags, m_settings.rejectedFlags),
                                  depositParams(chunk.firstPath, chunk.paths, stats.chunks));
                vk::computeBarrier(cmd);
                if (redistribute && storedSoFar > 0) {  // into the photons of the earlier rounds
                    m_deposit->recordRedistribution(cmd, storedSoFar);
                    vk::computeBarrier(cmd);
                }
            }
            m_compaction->recordCount(cmd, slotCount);
            vk::computeToHostBarrier(cmd);
        });
        // Read-back (docs/architecture.md): the chunk's kept photons, the map's growth.
        kept += m_compaction->keptCount();
        reserve(kept);
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            vk::transferToComputeBarrier(cmd);  // new room's zeroing
            m_compaction->recordAppend(cmd, slotCount, static_cast<uint32_t>(m_map.allocated()));
            if (densityControl) {  // the next round's current density sees this round's photons
                vk::computeBarrier(cmd);
                m_grid->record(cmd);
            }
            vk::computeToHostBarrier(cmd);
        });
        // Read-back (docs/architecture.md): the photons stored so far, the size of the next round's
        // redistribution dispatch.
        if (redistribute) m_state.download(&storedSoFar, sizeof(storedSoFar), gpu::kPhotonMapStateCount * sizeof(uint32_t));
        stats.chunks += 1;
        if (!stats.stopReason.empty()) {
            done += chunk.paths;
            break;
        }
    }
    // Each photon carries total power / paths: the paths traced, when the build stopped early.
    m_photonPower = static_cast<float>(m_totalPower / std::min(done, m_settings.paths));
    stats.candidates = candidateCount(stats.traced, m_settings.requiredFlags, m_settings.rejectedFlags);
    // Read-back (docs/architecture.md): the map's photon count, which sets the grid's cell size
    // (cellSizeFor) before the grid is built, and the statistics.
    uint32_t state[gpu::kPhotonMapStateSize];
    m_state.download(state, sizeof(state));
    stats.stored = state[gpu::kPhotonMapStateCount];
    stats.dropped = state[gpu::kPhotonMapStateDropped];
    m_lastStored = stats.stored;
    stats.traceSeconds = secondsSince(start);
    return buildGrid(stats, deposit);
}

PhotonMapStats PhotonMap::buildFromSlots(const vk::SegmentedBuffer& slots, uint32_t firstPath) {
    const bool deposit = m_settings.deposit.mode != gpu::kDepositAll;
    if (m_settings.deposit.mode == gpu::kDepositDensity)
        throw std::logic_error("PhotonMap::buildFromSlots: density control needs rounds of tracing");
    const uint32_t slotsPerPath = m_settings.maxDeposits;
    const uint64_t slotCount = uint64_t(m_settings.paths) * slotsPerPath;
    if (slots.allocated() < slotCount || slots.elementSize() != sizeof(gpu::GpuPhoton))
        throw std::logic_error("PhotonMap::buildFromSlots: slots too small");
    if (slotCount > m_capacity)
        throw InputError(fmt::format("{} photon slots exceed the map's capacity {} (selective update)", slotCount, m_capacity));
    PhotonMapStats stats;
    auto start = Clock::now();
    gpu::PhotonCompactParams params{};
    params.capacity = m_capacity;
    params.requiredFlags = m_settings.requiredFlags;
    params.rejectedFlags = m_settings.rejectedFlags;
    // The slots go through the compaction (and the deposit decision, which writes into them) in
    // chunks of m_chunkPaths paths, each copied into one scratch buffer: the persistent slots stay
    // undecided, and they may span more than one storage buffer's range.
    const uint32_t chunkSlots = m_chunkPaths * slotsPerPath;
    const vk::Buffer scratch(m_context, "photon slots to compact", VkDeviceSize(chunkSlots) * sizeof(gpu::GpuPhoton),
                             vk::kStorageUsage);
    const PhotonCompaction compaction(m_context, scratch, chunkSlots, m_map, m_state, params);
    uint32_t state[gpu::kPhotonMapStateSize];
    // One pass over the chunks: each chunk's photons (as they are, or as `decide` decides)
    // counted, then, when `append`, room for them in the map and their append. Returns the count.
    auto compact = [&](const PhotonDeposit* decide, bool append) {
        uint64_t kept = 0;
        for (uint32_t done = 0; done < m_settings.paths; done += m_chunkPaths) {
            const uint32_t paths = std::min(m_chunkPaths, m_settings.paths - done);
            const uint32_t count = paths * slotsPerPath;
            m_context.submitAndWait([&](VkCommandBuffer cmd) {
                if (done == 0 && append) {
                    m_map.fillZero(cmd);
                    m_state.fillZero(cmd);
                    if (decide) decide->recordClear(cmd);
                }
                const vk::SegmentedBuffer::ElementCopy chunk{0, uint64_t(done) * slotsPerPath, count};
                slots.recordCopyTo(cmd, scratch, {&chunk, 1});
                vk::transferToComputeBarrier(cmd);
                if (decide) {
                    decide->record(cmd, m_settings.deposit.importons->lookupParams(m_settings.requiredFlags, m_settings.rejectedFlags),
                                   depositParams(firstPath + done, paths, 0));
                    vk::computeBarrier(cmd);
                }
                compaction.recordCount(cmd, count);
                vk::computeToHostBarrier(cmd);
            });
            kept += compaction.keptCount();
            if (!append) continue;
            reserve(kept);
            m_context.submitAndWait([&](VkCommandBuffer cmd) {
                vk::transferToComputeBarrier(cmd);  // new room's zeroing
                compaction.recordAppend(cmd, count, static_cast<uint32_t>(m_map.allocated()));
                vk::computeToHostBarrier(cmd);
            });
        }
        if (append) m_state.download(state, sizeof(state));
        return kept;
    };
    if (deposit) {
        // The undecided photons are only counted (they set the cell size); the decided ones stored.
        stats.candidates = compact(nullptr, false);
        const PhotonDeposit decide(m_context, m_buffers, m_settings.deposit.importons->table(), scratch, chunkSlots, m_map,
                                   *m_grid, m_settings.segmentShift);
        compact(&decide, true);
    } else {
        compact(nullptr, true);
        stats.candidates = state[gpu::kPhotonMapStateCount] + state[gpu::kPhotonMapStateDropped];
    }
    m_photonPower = static_cast<float>(m_totalPower / m_settings.paths);
    stats.stored = state[gpu::kPhotonMapStateCount];
    stats.dropped = state[gpu::kPhotonMapStateDropped];
    m_lastStored = stats.stored;
    stats.chunks = 1;
    stats.traceSeconds = secondsSince(start);
    return buildGrid(stats, deposit);
}

uint64_t PhotonMap::bytes() const {
    return m_map.bytes() + m_grid->bytes() + (m_deposit ? m_deposit->redistributionBytes() : 0);
}

std::vector<gpu::GpuPhoton> PhotonMap::downloadPhotons() const {
    uint32_t count = 0;
    m_state.download(&count, sizeof(count), gpu::kPhotonMapStateCount * sizeof(uint32_t));
    return m_map.download<gpu::GpuPhoton>(count);
}

}  // namespace vkp
