#include "guiding/guide_cache.h"

namespace vkp {
namespace {

PhotonGridSettings cacheGrid(float cellSize, uint32_t tableSize) {
    PhotonGridSettings s;
    s.cellSize = cellSize;
    s.tableSize = tableSize;
    return s;
}

}  // namespace

GuideCache::GuideCache(vk::Context& context, const vk::SegmentedBuffer& photons, uint32_t slotCount, float cellSize,
                       uint32_t tableSize, const gpu::GuideParams& params)
    : m_grid(context, photons, slotCount, cacheGrid(cellSize, tableSize)), m_params(params),
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

}  // namespace vkp
