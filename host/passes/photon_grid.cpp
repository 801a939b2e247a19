#include "passes/photon_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

#include "shared/photon.glsl"
#include "util/errors.h"

namespace vkp {
namespace {

constexpr uint32_t kMinTableSize = 1u << 10;
constexpr uint32_t kMaxTableSize = 1u << 22;

VkDeviceSize atLeast16(VkDeviceSize bytes) { return std::max<VkDeviceSize>(16, bytes); }

}  // namespace

uint32_t PhotonGrid::tableSizeFor(uint32_t slotCount) {
    return std::clamp(std::bit_ceil(std::max(1u, slotCount / 2)), kMinTableSize, kMaxTableSize);
}

PhotonGrid::PhotonGrid(vk::Context& context, const vk::Buffer& photons, uint32_t slotCount,
                       const PhotonGridSettings& settings)
    : m_context(context), m_settings(settings),
      m_params([&] {
          gpu::PhotonGridParams p{};
          p.tableMask = (settings.tableSize ? std::bit_ceil(settings.tableSize) : tableSizeFor(slotCount)) - 1;
          p.slotCount = slotCount;
          p.requiredFlags = settings.requiredFlags;
          p.rejectedFlags = settings.rejectedFlags;
          return p;
      }()),
      m_cellStart(context, "photon grid cell starts", (m_params.tableMask + 2) * sizeof(uint32_t), vk::kStorageUsage),
      m_cursor(context, "photon grid cursors", (m_params.tableMask + 1) * sizeof(uint32_t), vk::kStorageUsage),
      m_sortedSlots(context, "photon grid sorted slots", atLeast16(VkDeviceSize(slotCount) * sizeof(uint32_t)),
                    vk::kStorageUsage),
      m_gridPhotons(context, "photon grid photons", atLeast16(VkDeviceSize(slotCount) * sizeof(gpu::GpuPhoton)),
                    vk::kStorageUsage),
      m_scan(context, m_cellStart, m_params.tableMask + 2),
      m_count(context), m_scatter(context), m_sortCells(context), m_copy(context) {
    setCellSize(settings.cellSize);
    std::vector<const vk::Buffer*> bindings(gpu::kGridBindingCount);
    bindings[gpu::kGridSlotBinding] = &photons;
    bindings[gpu::kGridCellStartBinding] = &m_cellStart;
    bindings[gpu::kGridCursorBinding] = &m_cursor;
    bindings[gpu::kGridSortedSlotBinding] = &m_sortedSlots;
    bindings[gpu::kGridPhotonBinding] = &m_gridPhotons;
    m_count.bind(bindings);
    m_scatter.bind(bindings);
    m_sortCells.bind(bindings);
    m_copy.bind(bindings);
}

void PhotonGrid::setCellSize(float cellSize) {
    if (!(cellSize > 0.0f) || !std::isfinite(cellSize))
        throw InputError(fmt::format("photon grid: the cell size must be positive (got {})", cellSize));
    m_settings.cellSize = cellSize;
    m_params.invCellSize = 1.0f / cellSize;
}

void PhotonGrid::record(VkCommandBuffer cmd) const {
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
    m_sortCells.record(cmd, tableSize(), m_params);
    vk::computeBarrier(cmd);
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
