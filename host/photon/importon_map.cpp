#include "photon/importon_map.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <fmt/format.h>

#include "photon/importance_lookup_pass.h"
#include "photon/importance_splat_pass.h"
#include "photon/importon_trace_pass.h"
#include "shared/importance.glsl"
#include "photon/photon_map.h"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace vkp {
namespace {

// occupancyCellSize aims at this many points, per point, in the point's own cell per k.
constexpr double kOccupancyPerK = 1.0;

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
    if (settings.k == 0) throw InputError("importance grid: a cell needs at least one importon (k >= 1)");
    const auto start = Clock::now();
    const uint32_t slots = settings.paths * settings.maxDeposits;
    m_slots = vk::Buffer(context, "importons", VkDeviceSize(slots) * sizeof(gpu::GpuImporton), vk::kStorageUsage);
    const ImportonTracePass trace(context, buffers, m_slots);
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
        trace.record(cmd, params);
        vk::computeToHostBarrier(cmd);
    });

    // Read-back (docs/architecture.md): the importons, for the grid's cell size (their occupancy),
    // the median path importance and, below, which test slots the camera sees directly.
    const std::vector<gpu::GpuImporton> importons = downloadImportons();
    std::vector<glm::vec3> positions;
    std::vector<float> pathImportance;
    for (const gpu::GpuImporton& p : importons) {
        if ((p.flags & gpu::kImportonValid) == 0) continue;
        positions.push_back(p.position);
        if (p.pathImportance > 0.0f) pathImportance.push_back(p.pathImportance);
    }
    m_stats.stored = positions.size();
    // The median: 1 / |x - y|^2 makes the mean follow a few importons near corners.
    if (!pathImportance.empty()) {
        std::nth_element(pathImportance.begin(), pathImportance.begin() + pathImportance.size() / 2, pathImportance.end());
        m_stats.medianPathImportance = pathImportance[pathImportance.size() / 2];
    }
    m_stats.cellSize = occupancyCellSize(positions, settings.k, sceneSurfaceArea(arrays));

    buildTable(context);
    m_stats.importanceScale = estimateImportanceScale(context, importons);
    m_stats.seconds = secondsSince(start);
}

// Splats the importons into a table with room for every cell at every level (at most one per
// importon and level); doubles it should the probes ever run out (an importon would be lost).
void ImportonMap::buildTable(vk::Context& context) {
    uint64_t entries = std::bit_ceil(std::max<uint64_t>(1024, m_stats.stored * gpu::kImportanceLevels / 4));
    for (;; entries *= 2) {
        m_table = vk::Buffer(context, "importance grid", entries * sizeof(gpu::ImportanceCell), vk::kStorageUsage);
        const ImportanceSplatPass splat(context, m_slots, m_table);
        gpu::ImportanceGridParams params = lookupParams();
        params.tableMask = static_cast<uint32_t>(entries - 1);
        params.slotCount = m_settings.paths * m_settings.maxDeposits;
        context.submitAndWait([&](VkCommandBuffer cmd) {
            m_table.fillZero(cmd);
            vk::transferToComputeBarrier(cmd);
            splat.record(cmd, params);
            vk::computeToHostBarrier(cmd);
        });
        // Read-back (docs/architecture.md): the table, to check that it counted every importon at
        // every level (a full table loses importons; it is then rebuilt twice as large).
        uint64_t counted = 0;
        for (const gpu::ImportanceCell& cell : m_table.download<gpu::ImportanceCell>())
            if (cell.key != gpu::kImportanceEmptyKey) counted += cell.count;
        if (counted == m_stats.stored * gpu::kImportanceLevels) break;
        if (entries >= (uint64_t(1) << 26)) throw std::runtime_error("importance grid: importons do not fit the table");
    }
    m_stats.tableSize = static_cast<uint32_t>(entries);
}

gpu::ImportanceGridParams ImportonMap::lookupParams(uint32_t requiredFlags, uint32_t rejectedFlags) const {
    gpu::ImportanceGridParams params{};
    params.invCellSize = 1.0f / m_stats.cellSize;
    params.tableMask = m_stats.tableSize ? m_stats.tableSize - 1 : 0;
    params.k = m_settings.k;
    params.requiredFlags = requiredFlags;
    params.rejectedFlags = rejectedFlags;
    return params;
}

// Keller & Wald: f is the reciprocal of the least importance that test rays from the camera
// sense, so p = 1 wherever the camera looks directly. The test rays are the first importon
// paths' directly seen importons.
float ImportonMap::estimateImportanceScale(vk::Context& context, const std::vector<gpu::GpuImporton>& importons) const {
    const uint32_t testSlots = std::min(m_settings.testRays, m_settings.paths) * m_settings.maxDeposits;
    vk::Buffer sensed(context, "importon test rays", VkDeviceSize(testSlots) * sizeof(glm::vec2), vk::kStorageUsage);
    const ImportonImportancePass lookup(context, m_table, m_slots, sensed);
    gpu::ImportanceGridParams params = lookupParams();
    params.slotCount = testSlots;
    context.submitAndWait([&](VkCommandBuffer cmd) {
        lookup.record(cmd, params);
        vk::computeToHostBarrier(cmd);
    });
    // Read-back (docs/architecture.md): the importance the test rays sense; f is a minimum over them.
    const auto values = sensed.download<glm::vec2>();
    float least = std::numeric_limits<float>::infinity();
    for (uint32_t slot = 0; slot < testSlots; ++slot)
        if ((importons[slot].flags & gpu::kImportonPrimary) != 0 && values[slot].x > 0.0f)
            least = std::min(least, values[slot].x);
    // The camera sees no surface that stores photons (only glass or mirrors with nothing behind,
    // say): no photon can reach the image, whatever is kept. Any scale will do; the render goes on
    // (it once stopped here with an error, refusing scenes the path tracer renders).
    if (!std::isfinite(least)) return 1.0f;
    return 1.0f / least;
}

}  // namespace vkp
