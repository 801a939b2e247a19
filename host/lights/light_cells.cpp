#include "lights/light_cells.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include "gpu_scene/gpu_scene.h"
#include "photon/photon_map.h"
#include "shared/light_selection.glsl"
#include "shared/photon_grid.glsl"
#include "shared/sampling.glsl"
#include "util/stopwatch.h"

namespace vkp {
namespace {

float bitsFloat(uint32_t u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

uint32_t floatBits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

struct CellKey {
    int x, y, z;
    bool operator==(const CellKey&) const = default;
};
struct CellKeyHash {
    size_t operator()(const CellKey& c) const {
        return (size_t(uint32_t(c.x)) * 73856093u) ^ (size_t(uint32_t(c.y)) * 19349663u) ^ (size_t(uint32_t(c.z)) * 83492791u);
    }
};

}  // namespace

LightCellStats buildLightCells(std::vector<float>& data, uint32_t lightCount, std::span<const gpu::GpuPhoton> photons,
                               float cellSize, uint32_t k, float floorProbability) {
    const gpu::LightSelectionArrays view{data, {}};
    const uint32_t cellsStart = gpu::lightCellsStart(view, lightCount);
    data.resize(cellsStart);
    LightCellStats stats;
    stats.cellSize = cellSize;
    const float invCellSize = 1.0f / cellSize;

    // Delivered power per light per cell.
    std::unordered_map<CellKey, std::unordered_map<uint32_t, double>, CellKeyHash> cells;
    for (const gpu::GpuPhoton& p : photons) {
        const uint32_t flags = gpu::photonFlags(p);
        if ((flags & gpu::kPhotonValid) == 0u || (flags & gpu::kPhotonPrimary) == 0u || p.lightIndex >= lightCount)
            continue;
        const glm::ivec3 c = gpu::gridCell(p.position, invCellSize);
        cells[{c.x, c.y, c.z}][p.lightIndex] += gpu::luminance(gpu::photonRelativePower(p));
        ++stats.photons;
    }

    // Each cell's K strongest lights, as a CDF.
    struct Cell {
        CellKey key;
        double total = 0.0;
        std::vector<std::pair<double, uint32_t>> lights;
    };
    std::vector<Cell> list;
    for (const auto& [key, lights] : cells) {
        Cell cell;
        cell.key = key;
        for (const auto& [light, power] : lights)
            if (power > 0.0) cell.lights.push_back({power, light});
        std::sort(cell.lights.begin(), cell.lights.end(), [](const auto& a, const auto& b) {
            return a.first != b.first ? a.first > b.first : a.second < b.second;
        });
        if (cell.lights.size() > k) cell.lights.resize(k);
        for (const auto& l : cell.lights) cell.total += l.first;
        if (cell.total > 0.0) list.push_back(std::move(cell));
    }
    // Deterministic order, strongest cells first: on a hash collision the stronger cell keeps the bucket.
    std::sort(list.begin(), list.end(), [](const Cell& a, const Cell& b) {
        if (a.total != b.total) return a.total > b.total;
        return std::tie(a.key.x, a.key.y, a.key.z) < std::tie(b.key.x, b.key.y, b.key.z);
    });
    uint32_t buckets = 1;
    while (buckets < 2 * list.size()) buckets *= 2;
    const uint32_t bucketFloats = gpu::lightCellBucketFloats(k);
    data.push_back(invCellSize);
    data.push_back(bitsFloat(buckets - 1));
    data.push_back(bitsFloat(k));
    data.push_back(floorProbability);
    const size_t table = data.size();
    data.resize(table + size_t(buckets) * bucketFloats, 0.0f);
    uint64_t candidates = 0;
    for (const Cell& cell : list) {
        const uint32_t bucket = gpu::gridHash(glm::ivec3(cell.key.x, cell.key.y, cell.key.z), buckets - 1);
        float* b = &data[table + size_t(bucket) * bucketFloats];
        if (floatBits(b[3]) != 0u) continue;  // taken by a stronger cell: this one falls back to the BVH
        b[0] = bitsFloat(uint32_t(cell.key.x));
        b[1] = bitsFloat(uint32_t(cell.key.y));
        b[2] = bitsFloat(uint32_t(cell.key.z));
        b[3] = bitsFloat(uint32_t(cell.lights.size()));
        double running = 0.0;
        for (size_t j = 0; j < cell.lights.size(); ++j) {
            running += cell.lights[j].first / cell.total;
            b[4 + 2 * j] = bitsFloat(cell.lights[j].second);
            b[4 + 2 * j + 1] = j + 1 == cell.lights.size() ? 1.0f : static_cast<float>(running);
        }
        ++stats.cells;
        candidates += cell.lights.size();
    }
    stats.buckets = buckets;
    stats.meanCandidates = stats.cells > 0 ? double(candidates) / stats.cells : 0.0;
    stats.bytes = (data.size() - cellsStart) * sizeof(float);
    return stats;
}

LightCellStats prepareLightCells(GpuScene& scene, const LightSampling& sampling, LightReach* reach) {
    const auto start = Clock::now();
    const SceneArrays& arrays = scene.arrays();
    const uint32_t lightCount = static_cast<uint32_t>(arrays.lights.size());
    float cellSize = sampling.cellSize;
    if (cellSize <= 0.0f) {
        const glm::vec3 e = scene.scene().bounds.extent();
        cellSize = std::max(std::max(e.x, std::max(e.y, e.z)) / 40.0f, 1e-4f);
    }
    std::vector<gpu::GpuPhoton> photons;
    if (lightCount > 0) {
        PhotonMapSettings settings;
        settings.paths = sampling.cellPhotons;
        settings.maxDeposits = 1;  // a path's first deposit is its primary photon when it has one
        settings.requiredFlags = gpu::kPhotonPrimary;
        settings.cellSize = cellSize;
        settings.seed = 0x4c434c53u;  // "LCLS": independent of the render's seeds
        PhotonMap map(scene.context(), scene.scene(), arrays, scene.buffers(), settings);
        map.build(0);
        photons = map.downloadPhotons();  // Read-back: the cells are built on the host
    }
    if (reach) *reach = buildLightReach(photons, lightCount, cellSize);
    std::vector<float> data = arrays.lightCdf;
    LightCellStats stats = buildLightCells(data, lightCount, photons, cellSize, sampling.cellK, sampling.cellFloor);
    stats.sameBuffer = scene.replaceLightSelection(std::move(data));
    stats.seconds = secondsSince(start);
    return stats;
}

}  // namespace vkp
