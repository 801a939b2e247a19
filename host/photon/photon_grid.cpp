#include "photon/photon_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

#include "shared/photon.glsl"
#include "util/errors.h"

namespace vkp {
namespace {

constexpr uint32_t kMinTableSize = 1u << 10;
// 8 M buckets (32 MiB): maps of 16 M photons and more share buckets between a few cells.
constexpr uint32_t kMaxTableSize = 1u << 23;

}  // namespace

uint32_t PhotonGrid::tableSizeFor(uint32_t slotCount) {
    return std::clamp(std::bit_ceil(std::max(1u, slotCount / 2)), kMinTableSize, kMaxTableSize);
}

PhotonGrid::PhotonGrid(vk::Context& context, const vk::SegmentedBuffer& photons, uint32_t slotCount,
                       const PhotonGridSettings& settings, uint32_t segmentShift)
    : m_context(context), m_input(photons), m_capacity(slotCount), m_settings(settings),
      m_params([&] {
          gpu::PhotonGridParams p{};
          p.tableMask = (settings.tableSize ? std::bit_ceil(settings.tableSize) : tableSizeFor(slotCount)) - 1;
          p.slotCount = 0;  // resize()
          p.requiredFlags = settings.requiredFlags;
          p.rejectedFlags = settings.rejectedFlags;
          return p;
      }()),
      m_cellStart(context, "photon grid cell starts", (m_params.tableMask + 2) * sizeof(uint32_t), vk::kStorageUsage),
      m_cursor(context, "photon grid cursors", (m_params.tableMask + 1) * sizeof(uint32_t), vk::kStorageUsage),
      // As many elements per segment as the input's: the arrays grow in the same steps.
      m_sortedSlots(context, "photon grid sorted slots", sizeof(uint32_t), slotCount,
                    segmentShift ? segmentShift : photons.segmentShift()),
      m_gridPhotons(context, "photon grid photons", sizeof(gpu::GpuPhoton), slotCount,
                    segmentShift ? segmentShift : photons.segmentShift()),
      m_scan(context, m_cellStart, m_params.tableMask + 2),
      m_count(context), m_scatter(context), m_sortCells(context), m_copy(context) {
    setCellSize(settings.cellSize);
    std::vector<const vk::Buffer*> bindings(gpu::kGridBindingCount);
    bindings[gpu::kGridSlotBinding] = &photons.table();
    bindings[gpu::kGridCellStartBinding] = &m_cellStart;
    bindings[gpu::kGridCursorBinding] = &m_cursor;
    bindings[gpu::kGridSortedSlotBinding] = &m_sortedSlots.table();
    bindings[gpu::kGridPhotonBinding] = &m_gridPhotons.table();
    m_count.bind(bindings);
    m_scatter.bind(bindings);
    m_sortCells.bind(bindings);
    m_copy.bind(bindings);
    resize(static_cast<uint32_t>(std::min<uint64_t>(slotCount, photons.allocated())));
}

void PhotonGrid::bindTable() {
    m_count.bind(gpu::kGridCellStartBinding, m_cellStart);
    m_count.bind(gpu::kGridCursorBinding, m_cursor);
    m_scatter.bind(gpu::kGridCellStartBinding, m_cellStart);
    m_scatter.bind(gpu::kGridCursorBinding, m_cursor);
    m_sortCells.bind(gpu::kGridCellStartBinding, m_cellStart);
    m_sortCells.bind(gpu::kGridCursorBinding, m_cursor);
    m_copy.bind(gpu::kGridCellStartBinding, m_cellStart);
    m_copy.bind(gpu::kGridCursorBinding, m_cursor);
}

void PhotonGrid::fitTable(uint32_t photons) {
    if (m_built) throw std::logic_error("PhotonGrid::fitTable after a build");
    const uint32_t size = tableSizeFor(photons);
    m_settings.tableSize = 0;  // grids made from these settings (radiance photons') size their own table
    if (size == tableSize()) return;
    m_retiredTables.push_back(std::move(m_cellStart));
    m_retiredTables.push_back(std::move(m_cursor));
    m_params.tableMask = size - 1;
    m_cellStart = vk::Buffer(m_context, "photon grid cell starts", (VkDeviceSize(size) + 1) * sizeof(uint32_t), vk::kStorageUsage);
    m_cursor = vk::Buffer(m_context, "photon grid cursors", VkDeviceSize(size) * sizeof(uint32_t), vk::kStorageUsage);
    m_scan = PrefixScan(m_context, m_cellStart, size + 1);
    bindTable();
}

void PhotonGrid::resize(uint32_t slots) {
    slots = static_cast<uint32_t>(std::min<uint64_t>({slots, m_capacity, m_input.allocated()}));
    m_sortedSlots.reserve(slots);
    m_gridPhotons.reserve(slots);
    m_params.slotCount = slots;
}

std::vector<gpu::GpuPhoton> PhotonGrid::downloadPhotons() const {
    return m_gridPhotons.download<gpu::GpuPhoton>(downloadPhotonCount());
}

void PhotonGrid::setCellSize(float cellSize) {
    if (!(cellSize > 0.0f) || !std::isfinite(cellSize))
        throw InputError(fmt::format("photon grid: the cell size must be positive (got {})", cellSize));
    m_settings.cellSize = cellSize;
    m_params.invCellSize = 1.0f / cellSize;
}

void PhotonGrid::record(VkCommandBuffer cmd) const {
    m_built = true;
    m_cellStart.fillZero(cmd);
    vk::transferToComputeBarrier(cmd);
    m_count.record(cmd, m_params.slotCount, m_params);
    vk::computeBarrier(cmd);
    m_scan.record(cmd);
    const VkBufferCopy region{0, 0, m_cursor.size()};
    vkCmdCopyBuffer(cmd, m_cellStart.handle(), m_cursor.handle(), 1, &region);
    vk::transferToComputeBarrier(cmd);
    m_scatter.record(cmd, m_params.slotCount, m_params);
    vk::computeBarrier(cmd);
    if (m_settings.sortBuckets) {
        m_sortCells.record(cmd, tableSize(), m_params);
        vk::computeBarrier(cmd);
    }
    m_copy.record(cmd, m_params.slotCount, m_params);
}

gpu::PhotonGridView PhotonGrid::view(float photonPower) const {
    gpu::PhotonGridView v{};
    v.invCellSize = m_params.invCellSize;
    v.tableMask = m_params.tableMask;
    v.photonPower = photonPower;
    return v;
}

uint32_t PhotonGrid::downloadPhotonCount() const {
    uint32_t count = 0;
    m_cellStart.download(&count, sizeof(count), VkDeviceSize(tableSize()) * sizeof(uint32_t));
    return count;
}

}  // namespace vkp
