#include "lights/light_reach.h"

#include <algorithm>
#include <unordered_set>

#include "bvh/scene_bvh.h"
#include "shared/photon_grid.glsl"

namespace vkp {
namespace {

uint64_t cellKey(glm::ivec3 c) {
    const auto part = [](int v) { return uint64_t(uint32_t(v + (1 << 20)) & 0x1fffffu); };
    return (part(c.x) << 42) | (part(c.y) << 21) | part(c.z);
}

}  // namespace

LightReach buildLightReach(std::span<const gpu::GpuPhoton> photons, uint32_t lightCount, float cellSize) {
    LightReach reach;
    reach.cellSize = cellSize;
    reach.lightCount = lightCount;
    const float invCellSize = 1.0f / cellSize;
    for (const gpu::GpuPhoton& p : photons) {
        const uint32_t flags = gpu::photonFlags(p);
        if ((flags & gpu::kPhotonValid) == 0u || (flags & gpu::kPhotonPrimary) == 0u || p.lightIndex >= lightCount)
            continue;
        reach.lightsOfCell[cellKey(gpu::gridCell(p.position, invCellSize))].push_back(p.lightIndex);
    }
    for (auto& [key, lights] : reach.lightsOfCell) {
        std::sort(lights.begin(), lights.end());
        lights.erase(std::unique(lights.begin(), lights.end()), lights.end());
    }
    return reach;
}

std::vector<bool> lightsReachingView(const SceneArrays& arrays, const LightReach& reach, const gpu::GpuCamera& camera,
                                     uint32_t width, uint32_t height, uint32_t rays) {
    std::vector<bool> keep(arrays.lights.size(), false);
    for (size_t i = 0; i < arrays.lights.size(); ++i) {
        const uint32_t type = arrays.lights[i].type;
        keep[i] = !(type == gpu::kLightTriangle || type == gpu::kLightPoint || type == gpu::kLightSpot);
    }
    if (reach.cellSize <= 0.0f || reach.lightCount != arrays.lights.size()) return std::vector<bool>(keep.size(), true);
    const float invCellSize = 1.0f / reach.cellSize;
    const gpu::BvhArrays bvh = arrays.bvhArrays();
    std::unordered_set<uint64_t> visible;
    for (uint32_t y = 0; y < rays; ++y) {
        for (uint32_t x = 0; x < rays; ++x) {
            const glm::vec2 pixel((x + 0.5f) * width / rays, (y + 0.5f) * height / rays);
            const glm::vec3 org = gpu::cameraRayOrigin(camera, width, height, pixel);
            const glm::vec3 dir = gpu::cameraRayDirection(camera, width, height, pixel);
            const RayHit hit = closestHit(bvh, org, dir, 1e30f, true);
            if (!hit.hit) continue;
            const glm::ivec3 c = gpu::gridCell(org + hit.t * dir, invCellSize);
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) visible.insert(cellKey(c + glm::ivec3(dx, dy, dz)));
        }
    }
    for (uint64_t key : visible) {
        const auto it = reach.lightsOfCell.find(key);
        if (it == reach.lightsOfCell.end()) continue;
        for (uint32_t light : it->second) keep[light] = true;
    }
    return keep;
}

}  // namespace vkp
