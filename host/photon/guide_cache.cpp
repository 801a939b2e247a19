#include "photon/guide_cache.h"

#include <algorithm>

#include "photon/photon_map.h"

namespace vkp {
namespace {

// Cache cells are this many times the even-spread radius of k guiding photons: about 36k/pi
// photons on a flat cell (docs/benchmarks.md, "Guiding cache cells of six radii").
constexpr float kCacheCellFactor = 6.0f;

PhotonGridSettings cacheGrid(float cellSize, uint32_t tableSize, uint32_t rejectedFlags) {
    PhotonGridSettings s;
    s.cellSize = cellSize;
    s.tableSize = tableSize;
    s.rejectedFlags = rejectedFlags;
    s.sortBuckets = false;  // the cache build's sums do not depend on the photons' order
    return s;
}

}  // namespace

GuideCache::GuideCache(vk::Context& context, const vk::SegmentedBuffer& photons, uint32_t slotCount, float cellSize,
                       uint32_t tableSize, const gpu::GuideParams& params, uint32_t rejectedFlags)
    : m_grid(context, photons, slotCount, cacheGrid(cellSize, tableSize, rejectedFlags)), m_params(params),
      m_cells(context, "guide cache cells", VkDeviceSize(m_grid.tableSize()) * 4 * sizeof(int32_t), vk::kStorageUsage),
      m_cdfs(context, "guide cache grids",
             VkDeviceSize(m_grid.tableSize()) * gpu::kNormalBins * gpu::kMaxGuideCells * sizeof(float),
             vk::kStorageUsage),
      m_irradiance(context, "guide cache irradiance",
                   VkDeviceSize(m_grid.tableSize()) * gpu::kNormalBins * sizeof(glm::vec4), vk::kStorageUsage),
      m_build(context) {
    m_params.grid = m_grid.view(params.grid.photonPower);
    m_build.bind(gpu::kGuideCacheCellStartBinding, m_grid.cellStart());
    m_build.bind(gpu::kGuideCachePhotonBinding, m_grid.photons());
    m_build.bind(gpu::kGuideCacheCellsBinding, m_cells);
    m_build.bind(gpu::kGuideCacheCdfsBinding, m_cdfs);
    m_build.bind(gpu::kGuideCacheIrradianceBinding, m_irradiance);
}

void GuideCache::record(VkCommandBuffer cmd) const {
    m_grid.record(cmd);
    vk::computeBarrier(cmd);
    m_build.record(cmd, uint64_t(m_grid.tableSize()) * gpu::kNormalBins, m_params);
}

std::unique_ptr<GuideCache> makeGuideCache(vk::Context& context, const vk::SegmentedBuffer& gridPhotons, uint64_t stored,
                                           uint64_t guidePhotons, uint32_t k, double area, const gpu::GuideParams& params,
                                           uint32_t rejectedFlags) {
    const float cellSize = kCacheCellFactor * evenSpreadRadius(k, guidePhotons, area);
    const double cells = area / (double(cellSize) * cellSize);
    const auto table = static_cast<uint32_t>(std::clamp(2.0 * cells, 1024.0, double(1u << 20)));
    // Only the first `stored` entries of the grid's photon array are written.
    const auto slots = static_cast<uint32_t>(std::clamp<uint64_t>(stored, 1, UINT32_MAX));
    return std::make_unique<GuideCache>(context, gridPhotons, slots, cellSize, table, params, rejectedFlags);
}

}  // namespace vkp
