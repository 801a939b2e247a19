#include "render/importon_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <fmt/format.h>

#include "passes/scene_pass.h"
#include "render/photon_map.h"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {
namespace {

// Nearest-importon searches reach one cell, so they visit one ring of cells: on lavapipe, a
// lookup's cost is mostly the cells it visits (two rings: 153 cells, one ring: 28).
constexpr float kSearchRadiusCells = 1.0f;
// occupancyCellSize aims at this many points, per point, in the point's own cell per k: cells
// about as wide as the k-nearest radius, so a search visits few points beyond its k.
constexpr double kOccupancyPerK = 0.5;

uint64_t cellKey(const glm::vec3& p, float invCellSize) {
    const glm::ivec3 c = gpu::gridCell(p, invCellSize);
    return (uint64_t(uint32_t(c.x) & 0x1fffffu) << 42) | (uint64_t(uint32_t(c.y) & 0x1fffffu) << 21) |
           uint64_t(uint32_t(c.z) & 0x1fffffu);
}

// Point-weighted mean number of points in a point's cell.
double meanOccupancy(const std::vector<glm::vec3>& points, float cellSize) {
    std::unordered_map<uint64_t, uint32_t> counts;
    counts.reserve(points.size());
    for (const glm::vec3& p : points) counts[cellKey(p, 1.0f / cellSize)] += 1;
    double sumSquares = 0.0;
    for (const auto& [key, n] : counts) sumSquares += double(n) * n;
    return sumSquares / double(points.size());
}

}  // namespace

float occupancyCellSize(const std::vector<glm::vec3>& points, uint32_t k, double area) {
    float cellSize = evenSpreadRadius(k, points.size(), area);
    if (points.empty()) return cellSize;
    const double target = kOccupancyPerK * k;
    for (int i = 0; i < 4; ++i) {
        const double occupancy = meanOccupancy(points, cellSize);
        // Points lie on surfaces: a cell's share grows with the square of its size.
        cellSize *= static_cast<float>(std::clamp(std::sqrt(target / occupancy), 0.25, 4.0));
    }
    return cellSize;
}

ImportonMap::ImportonMap(vk::Context& context, const SceneArrays& arrays, const SceneBuffers& buffers,
                         const gpu::GpuCamera& camera, uint32_t width, uint32_t height,
                         const ImportonSettings& settings)
    : m_settings(settings) {
    if (settings.paths == 0 || settings.maxDeposits == 0)
        throw InputError("--importons must be at least 1");
    if (settings.k == 0 || settings.k > gpu::kMaxGatherK)
        throw InputError(fmt::format("importon lookups: k {} must be between 1 and {}", settings.k, gpu::kMaxGatherK));
    const auto start = Clock::now();
    const uint32_t slots = settings.paths * settings.maxDeposits;
    m_slots = vk::Buffer(context, "importons", VkDeviceSize(slots) * sizeof(gpu::GpuPhoton), vk::kStorageUsage);
    const ScenePass trace(context, "importon_trace.comp", buffers, {&m_slots}, sizeof(gpu::ImportonTraceParams));
    gpu::ImportonTraceParams params{};
    params.camera = camera;
    params.width = width;
    params.height = height;
    params.pathCount = settings.paths;
    params.maxDeposits = settings.maxDeposits;
    params.seed = settings.seed;
    params.maxDepth = settings.maxDepth;
    context.submitAndWait([&](VkCommandBuffer cmd) {
        m_slots.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
        trace.record(cmd, settings.paths, params);
        vk::computeToHostBarrier(cmd);
    });

    const std::vector<gpu::GpuPhoton> importons = downloadImportons();
    std::vector<glm::vec3> positions;
    double pathImportanceSum = 0.0;
    uint64_t seenThroughBounce = 0;
    for (const gpu::GpuPhoton& p : importons) {
        if ((gpu::photonFlags(p) & gpu::kPhotonValid) == 0) continue;
        positions.push_back(p.position);
        const float w = gpu::photonRelativePower(p).y;
        if (w > 0.0f) {
            pathImportanceSum += w;
            seenThroughBounce += 1;
        }
    }
    m_stats.stored = positions.size();
    m_stats.meanPathImportance = seenThroughBounce ? static_cast<float>(pathImportanceSum / seenThroughBounce) : 0.0f;
    m_stats.cellSize = occupancyCellSize(positions, settings.k, sceneSurfaceArea(arrays));

    PhotonGridSettings grid;
    grid.cellSize = m_stats.cellSize;
    m_grid = std::make_unique<PhotonGrid>(context, m_slots, slots, grid);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        m_grid->record(cmd);
        vk::computeBarrier(cmd);
    });
    m_stats.importanceScale = estimateImportanceScale(context, buffers, importons);
    m_stats.seconds = secondsSince(start);
}

gpu::ImportanceLookupParams ImportonMap::lookupParams(uint32_t requiredFlags, uint32_t rejectedFlags) const {
    gpu::ImportanceLookupParams params{};
    params.requiredFlags = requiredFlags;
    params.rejectedFlags = rejectedFlags;
    params.importons = m_grid->view(1.0f);
    params.k = m_settings.k;
    params.maxRadius = kSearchRadiusCells * m_stats.cellSize;
    return params;
}

// Keller & Wald: f is the reciprocal of the least importance that test rays from the camera
// sense, so p = 1 wherever the camera looks directly. The test rays are the first importon
// paths' directly seen importons.
float ImportonMap::estimateImportanceScale(vk::Context& context, const SceneBuffers& buffers,
                                           const std::vector<gpu::GpuPhoton>& importons) const {
    const uint32_t testSlots = std::min(m_settings.testRays, m_settings.paths) * m_settings.maxDeposits;
    vk::Buffer sensed(context, "importon test rays", VkDeviceSize(testSlots) * sizeof(glm::vec2), vk::kStorageUsage);
    const ScenePass lookup(context, "importance_lookup.comp", buffers,
                           {&m_grid->cellStart(), &m_grid->photons(), &m_slots, &sensed},
                           sizeof(gpu::ImportanceLookupParams));
    gpu::ImportanceLookupParams params = lookupParams();
    params.slotCount = testSlots;
    context.submitAndWait([&](VkCommandBuffer cmd) {
        lookup.record(cmd, testSlots, params);
        vk::computeToHostBarrier(cmd);
    });
    const auto values = sensed.download<glm::vec2>();
    float least = std::numeric_limits<float>::infinity();
    for (uint32_t slot = 0; slot < testSlots; ++slot)
        if ((gpu::photonFlags(importons[slot]) & gpu::kPhotonPrimary) != 0 && values[slot].x > 0.0f)
            least = std::min(least, values[slot].x);
    if (!std::isfinite(least))
        throw InputError("importance-driven deposition: the camera sees no surface that stores photons");
    return 1.0f / least;
}

}  // namespace vkp
