#include "render/path_guide.h"

#include <algorithm>

#include <fmt/format.h>

#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {
namespace {

// Gathers search up to this many times the map's even-spread radius for k photons.
constexpr float kGuideRadiusFactor = 2.0f;
// Cache cells are three times the even-spread radius: about 9k/pi photons on a flat cell. Grid
// noise, not spatial detail, limits the cache (docs/benchmarks.md: factors 1 to 4 measured).
constexpr float kCacheCellFactor = 3.0f;

}  // namespace

void checkGuideSettings(const GuideRenderSettings& g) {
    if (g.photons == 0) throw InputError("--guide-photons must be at least 1");
    if (g.k == 0 || g.k > gpu::kMaxGatherK)
        throw InputError(fmt::format("--guide-k {}: must be between 1 and {}", g.k, gpu::kMaxGatherK));
    if (g.gridU == 0 || g.gridV == 0 || g.gridU * g.gridV > gpu::kMaxGuideCells || g.gridV > 255)
        throw InputError(fmt::format("--guide-grid {}x{}: needs 1 <= m * n <= {}", g.gridU, g.gridV,
                                     gpu::kMaxGuideCells));
    if (g.adaptPhotons > 0xffff) throw InputError(fmt::format("--guide-adapt {}: at most 65535", g.adaptPhotons));
    if (!(g.mix >= 0.0f && g.mix <= 1.0f)) throw InputError(fmt::format("--guide-mix {}: must lie in [0, 1]", g.mix));
}

PathGuide::PathGuide(vk::Context& context, const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers,
                     const GuideRenderSettings& g, uint32_t seed) {
    checkGuideSettings(g);
    const auto start = Clock::now();
    PhotonMapSettings mapSettings;
    mapSettings.paths = g.photons;
    mapSettings.seed = seed;
    mapSettings.rejectedFlags = gpu::kPhotonPrimary;
    const double area = sceneSurfaceArea(arrays);
    mapSettings.cellSizeFor = [&](uint64_t stored) { return evenSpreadRadius(g.k, stored, area); };
    m_map = std::make_unique<PhotonMap>(context, scene, arrays, buffers, mapSettings);
    m_mapStats = m_map->build(0);
    m_searchRadius = kGuideRadiusFactor * m_mapStats.cellSize;
    m_params.grid = m_map->grid().view(m_map->photonPower());
    m_params.mix = g.mix;
    m_params.k = g.k;
    m_params.maxRadius = m_searchRadius;
    m_params.gridSize = g.gridU | (g.gridV << 8) | (g.adaptPhotons << 16);
    m_shader = "guided_pathtrace.comp";
    // No indirect photons (a scene lit only directly): nothing to guide by, sample the BSDF.
    if (m_mapStats.stored == 0) m_params.mix = 0.0f;
    if (g.cache && m_mapStats.stored > 0) {
        const float cellSize = kCacheCellFactor * m_mapStats.cellSize;
        const double cells = area / (double(cellSize) * cellSize);
        const auto table = static_cast<uint32_t>(std::clamp(2.0 * cells, 1024.0, double(1u << 20)));
        // Only the first `stored` entries of the grid's photon buffer are written.
        const auto stored = static_cast<uint32_t>(std::max<uint64_t>(1, m_mapStats.stored));
        m_cache = std::make_unique<GuideCache>(context, m_map->grid().photons(), stored, cellSize, table, m_params);
        context.submitAndWait([&](VkCommandBuffer cmd) {
            vk::computeBarrier(cmd);
            m_cache->record(cmd);
        });
        m_params = m_cache->params();
        m_shader = "guided_cached_pathtrace.comp";
    }
    m_seconds = secondsSince(start);
}

std::vector<const vk::Buffer*> PathGuide::buffers() const {
    if (m_cache) return {&m_cache->cells(), &m_cache->cdfs(), &m_cache->irradiance()};
    return {&m_map->grid().cellStart(), &m_map->grid().photons()};
}

void PathGuide::addStats(RenderStats& stats) const {
    stats.photonPathsTraced += m_mapStats.traced.emitted;
    stats.globalPhotons = m_mapStats.stored;
    stats.photonsDropped += m_mapStats.dropped;
    stats.photonSeconds += m_seconds;
    stats.photonMapBytes += m_map->bytes() + (m_cache ? m_cache->bytes() : 0);
    stats.globalRadius = m_searchRadius;
}

}  // namespace vkp
