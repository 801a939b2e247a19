// The photon hash grid pass (shaders/grid_*.comp): reads photon records in their fixed slots and
// writes the photons a map keeps, sorted by the hash of their cell, with the start of every
// bucket — a counting sort (count, GPU prefix sum, scatter, per-bucket sort for determinism, copy), no
// CPU round trip and no linked lists. Gathers read it through shaders/photon/photon_gather.glsl.
#pragma once

#include <cstdint>
#include <vector>

#include "passes/prefix_scan.h"
#include "shared/kernels/grid_build.glsl"
#include "shared/photon.glsl"
#include "shared/photon_grid.glsl"
#include "vk/buffer.h"
#include "vk/segmented_buffer.h"
#include "vk/kernel.h"

namespace vkp {

struct PhotonGridSettings {
    float cellSize = 0.05f;       // world units; gathers of radius r visit ceil(2r / cellSize + 1)^3 cells
    uint32_t requiredFlags = 0;   // kPhoton* flags a photon must carry to enter the map
    uint32_t rejectedFlags = 0;   // flags that keep it out
    uint32_t tableSize = 0;       // buckets (a power of two); 0: from the slot count
    // Sort each bucket by slot, so sums over a bucket come out the same on every run. Without it a
    // bucket's photons are in the order the scatter's atomics placed them, which varies: only for
    // readers whose results do not depend on it (the guiding cache). The sort runs one invocation
    // per bucket and passes lavapipe's loop budget in buckets of thousands of photons.
    bool sortBuckets = true;
};

class PhotonGrid {
public:
    // A grid over up to `slotCount` photon slots of `photons` (empty slots are skipped), at first
    // over those `photons` has allocated (resize changes that). The table's size follows slotCount;
    // the grid's arrays have segments of 2^segmentShift elements (0: as many as the input's).
    PhotonGrid(vk::Context& context, const vk::SegmentedBuffer& photons, uint32_t slotCount,
               const PhotonGridSettings& settings, uint32_t segmentShift = 0);

    // The next builds cover slots [0, slots) of the input (at most its allocated slots and the
    // grid's slotCount): allocates the grid's own arrays for them.
    void resize(uint32_t slots);

    // Sizes the hash table for `photons` (tableSizeFor, whatever settings.tableSize said) before the grid's first build, so a map
    // that keeps few of its slots' photons has a table of its photons' size, not its slots'.
    // Kernels bound to the old table before (density control's) keep valid buffers; rebind them
    // to read the new one. Throws std::logic_error after a build.
    void fitTable(uint32_t photons);

    // Changes the cell size for the next build (the table and buffers stay).
    void setCellSize(float cellSize);

    // Records the build; the caller places a barrier before (after the photon writes) and after.
    void record(VkCommandBuffer cmd) const;

    const vk::Buffer& cellStart() const { return m_cellStart; }  // tableSize + 1 entries
    // Bucket order, a segmented array's table (bind it; vk/segmented_buffer.h); only the first
    // downloadPhotonCount() entries are written by a build.
    const vk::Buffer& photons() const { return m_gridPhotons.table(); }
    // Map slot of each grid entry (the order the grid's photons follow), likewise segmented.
    const vk::Buffer& sortedSlots() const { return m_sortedSlots.table(); }
    const vk::SegmentedBuffer& photonArray() const { return m_gridPhotons; }
    uint32_t slotCount() const { return m_params.slotCount; }   // slots the builds cover now
    uint32_t capacity() const { return m_capacity; }            // slots they may cover at most
    // Device memory of the grid: the table, sorted slots and photons.
    uint64_t bytes() const { return m_cellStart.size() + m_cursor.size() + m_sortedSlots.bytes() + m_gridPhotons.bytes(); }
    // The first downloadPhotonCount() photons in bucket order (after the build has completed).
    std::vector<gpu::GpuPhoton> downloadPhotons() const;
    uint32_t tableSize() const { return m_params.tableMask + 1; }
    const PhotonGridSettings& settings() const { return m_settings; }
    // What a gather shader needs to find its photons, with the watts of a relative power of 1.
    gpu::PhotonGridView view(float photonPower) const;
    // Photons in the grid, read back from the device (after the build has completed).
    uint32_t downloadPhotonCount() const;

    // Table size for a buffer of `slotCount` slots: a power of two near half the slot count.
    static uint32_t tableSizeFor(uint32_t slotCount);

private:
    vk::Context& m_context;
    const vk::SegmentedBuffer& m_input;
    uint32_t m_capacity;
    PhotonGridSettings m_settings;
    gpu::PhotonGridParams m_params{};
    vk::Buffer m_cellStart;
    vk::Buffer m_cursor;
    vk::SegmentedBuffer m_sortedSlots;
    vk::SegmentedBuffer m_gridPhotons;
    PrefixScan m_scan;
    vk::Kernel<gpu::GridCountKernel> m_count;
    vk::Kernel<gpu::GridScatterKernel> m_scatter;
    vk::Kernel<gpu::GridSortCellsKernel> m_sortCells;
    vk::Kernel<gpu::GridCopyKernel> m_copy;
    std::vector<vk::Buffer> m_retiredTables;  // replaced by fitTable: descriptor sets made before may name them
    mutable bool m_built = false;
    void bindTable();
};

}  // namespace vkp
