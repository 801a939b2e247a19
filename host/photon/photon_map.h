// One photon map on the GPU: photon paths traced in chunks (photon/photon_tracer.h), the photons
// the map keeps appended densely in path order (photon/photon_compaction.h), and the hash grid
// over them (photon/photon_grid.h). Chunking keeps each chunk's slot buffer within the device's
// maxStorageBufferRange; the map and its grid are segmented arrays (vk/segmented_buffer.h) that
// grow chunk by chunk, so a map holds as many photons as the device's memory does.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "photon/photon_compaction.h"
#include "photon/photon_deposit.h"
#include "photon/photon_grid.h"
#include "photon/photon_tracer.h"
#include "render/render_control.h"

namespace vkp {

class ImportonMap;  // photon/importon_map.h: what importance deposition reads

// Which traced photons a map keeps (--deposit; docs/importance-deposition.md).
struct DepositSettings {
    uint32_t mode = gpu::kDepositAll;        // kDeposit*
    const ImportonMap* importons = nullptr;  // required unless the mode is kDepositAll
    float epsilon = 0.01f;                   // --deposit-epsilon: floor of the acceptance probability
    bool cutoff = false;                     // --deposit-cutoff: drop below epsilon (biased) instead of clamping
    float densityAccuracy = 0.0f;            // --density-accuracy C: required density = C * path importance
    float minDensity = 0.0f;                 // required density where the path importance is lower
    float densityFloor = 0.1f;               // least acceptance where density is required (weights <= 10)
    bool redistribute = true;                // density control: rejected power to the neighbours (Suykens &
                                             // Willems); false: Russian-roulette weighting (--density-roulette)
    uint32_t densityK = 16;                  // nearest stored photons per current-density estimate
    uint32_t rounds = 8;                     // density control: trace, deposit, rebuild the grid, repeat
};

struct PhotonMapSettings {
    uint32_t paths = kDefaultPhotonPaths;      // photon paths emitted per build
    uint32_t maxDeposits = kDefaultMaxDeposits;     // stored photons per path at most (1 suffices for caustics:
                                  // a caustic photon is always a path's first deposit)
    uint32_t seed = 0;
    uint32_t requiredFlags = 0;   // which photons the map keeps (PhotonGridSettings)
    uint32_t rejectedFlags = 0;
    float cellSize = 0.05f;
    // When set, chooses the grid's cell size from the number of photons stored by each build
    // (with importance deposition: deposited before the decision, the density where p = 1).
    std::function<float(uint64_t photons)> cellSizeFor;
    uint32_t chunkPaths = 0;      // paths per traced chunk; 0: at most kMaxChunkPaths and 2 M slots
    DepositSettings deposit;
    // Photons per segment of the map and its grid, log2 (0: 128 MiB segments, 4 M photons).
    // Lower values split small maps over many buffers: tests compare them with one buffer.
    uint32_t segmentShift = 0;
    // Size the grid's hash table for the photons of the first build (PhotonGrid::fitTable) rather
    // than for the slots. Off for a map whose grid a pass binds before the first build (the
    // progressive integrator's): the table's buffer must not change under it.
    bool fitGridTable = true;
    // Checked between chunks (may be null): a stopped build keeps the chunks traced so far, with
    // the photon power normalised by the paths actually traced (at least one small chunk).
    const RenderControl* control = nullptr;
};

struct PhotonMapStats {
    PhotonCounters traced;        // over all chunks
    uint64_t candidates = 0;      // deposits of the map's kind the paths made (before any deposit decision)
    uint64_t stored = 0;          // photons in the map
    uint64_t dropped = 0;         // kept photons beyond the map's capacity
    uint64_t bytes = 0;           // device memory of the map and its grid after the build
    uint32_t chunks = 0;
    float cellSize = 0.0f;
    double traceSeconds = 0.0;    // tracing and compaction
    double gridSeconds = 0.0;
    double gridCpuSeconds = 0.0;  // the process's CPU time during the grid build (every thread)
    std::string stopReason;       // non-empty when the control stopped the build early
};

// Total area of the scene's triangles (square world units).
double sceneSurfaceArea(const SceneArrays& arrays);

// The radius of a disk holding k photons if `photons` spread evenly over `area`: the search scale
// of a map's k-nearest estimates (its grid's cell size).
float evenSpreadRadius(uint32_t k, uint64_t photons, double area);

class PhotonMap {
public:
    PhotonMap(vk::Context& context, const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers,
              const PhotonMapSettings& settings);
    ~PhotonMap();

    // Traces settings.paths paths with Halton indices firstPath... into a fresh map and builds
    // its grid (progressive passes call it again with fresh index ranges).
    PhotonMapStats build(uint32_t firstPath);
    // Compacts per-path slots traced elsewhere (settings.paths paths with Halton indices
    // firstPath..., path i in slots i * maxDeposits + k: the selective update's persistent slots,
    // photon/selective_photon_update.h) into the map and builds its grid. With --deposit
    // importance the deposit decision runs on a copy of the slots against the current importons
    // (as build() decides; density control is not supported). The stats' traced counters stay zero.
    PhotonMapStats buildFromSlots(const vk::SegmentedBuffer& slots, uint32_t firstPath);

    const PhotonGrid& grid() const { return *m_grid; }
    const PhotonMapSettings& settings() const { return m_settings; }
    // The scene the map traces in (a selective update traces the map's paths itself).
    const Scene& scene() const { return m_scene; }
    const SceneArrays& arrays() const { return m_arrays; }
    const SceneBuffers& buffers() const { return m_buffers; }
    // Watts carried by a photon of relative power 1 (total light power / paths of one build).
    float photonPower() const { return m_photonPower; }
    uint32_t capacity() const { return m_capacity; }
    // Photons in the map after its last build (or selective update).
    uint64_t stored() const { return m_lastStored; }
    // Device memory of the map's photons and its grid, and density control's redistribution sums
    // (allocated in segments as the map fills; the traced chunk's slots are scratch).
    uint64_t bytes() const;
    // Photons per segment of the map's buffers.
    uint64_t segmentPhotons() const { return uint64_t(1) << m_map.segmentShift(); }
    // The map's photons, in path order (after a build).
    std::vector<gpu::GpuPhoton> downloadPhotons() const;

private:
    double m_totalPower;
    gpu::PhotonDepositParams depositParams(uint32_t firstPath, uint32_t paths, uint32_t round) const;

    vk::Context& m_context;
    const Scene& m_scene;
    const SceneArrays& m_arrays;
    const SceneBuffers& m_buffers;
    PhotonMapSettings m_settings;
    PhotonTracer m_tracer;
    uint32_t m_chunkPaths;
    float m_photonPower;
    uint32_t m_capacity;
    vk::SegmentedBuffer m_map;
    vk::Buffer m_state;
    std::unique_ptr<PhotonGrid> m_grid;
    std::unique_ptr<PhotonCompaction> m_compaction;  // bound to the tracer's slots (allocated by the first chunk)
    std::unique_ptr<PhotonDeposit> m_deposit;        // likewise; only with a deposit mode other than all
    uint64_t m_lastStored = 0;
    bool m_gridBuilt = false;  // the grid's table is fitted to the first build's photons
    // Allocates the map's segments for `photons` and the grid's for all the map holds.
    void reserve(uint64_t photons);
    // The hash grid over the photons stored (or, deciding deposits, the candidates), timed into
    // `stats`, with the map's memory: the last step of build() and buildFromSlots().
    PhotonMapStats buildGrid(PhotonMapStats stats, bool deposit);
};

}  // namespace vkp
