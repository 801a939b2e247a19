#include "photon/scene_changes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vkp {
namespace {

// FNV-1a over the bytes of each vector in turn.
class Hasher {
public:
    template <typename T> void add(const std::vector<T>& values) {
        add(values.data(), values.size() * sizeof(T));
        const uint64_t n = values.size();
        add(&n, sizeof(n));
    }
    void add(const void* data, size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < bytes; ++i) m_hash = (m_hash ^ p[i]) * 0x100000001b3ull;
    }
    uint64_t value() const { return m_hash; }

private:
    uint64_t m_hash = 0xcbf29ce484222325ull;
};

uint64_t staticHash(const SceneArrays& arrays) {
    Hasher h;
    h.add(arrays.triangles);
    h.add(arrays.shading);
    h.add(arrays.materials);
    h.add(arrays.textures);
    h.add(arrays.environment);
    const size_t lights = arrays.lights.size();
    h.add(arrays.lightCdf.data(), std::min(lights, arrays.lightCdf.size()) * sizeof(float));
    h.add(&arrays.totalLightPower, sizeof(arrays.totalLightPower));
    return h.value();
}

}  // namespace

Bounds transformedBounds(const Bounds& object, const glm::mat4& transform) {
    Bounds world;
    if (object.empty()) return world;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? object.max.x : object.min.x, (corner & 2) ? object.max.y : object.min.y,
                          (corner & 4) ? object.max.z : object.min.z);
        world.grow(glm::vec3(transform * glm::vec4(p, 1.0f)));
    }
    return world;
}

float regionMargin(float extent) { return 1.0e-3f * std::max(1.0f, extent); }

SceneSnapshot snapshotScene(const Scene& scene, const SceneArrays& arrays, uint64_t generation,
                            const SceneSnapshot* previous) {
    SceneSnapshot s;
    for (const Instance& instance : scene.instances) {
        s.instanceMeshes.push_back(instance.mesh);
        s.instanceTransforms.push_back(instance.transform);
    }
    for (const Mesh& mesh : scene.meshes) s.meshBounds.push_back(mesh.bounds);
    s.lights = arrays.lights;
    s.generation = generation;
    s.staticHash = previous && previous->generation == generation ? previous->staticHash : staticHash(arrays);
    float extent = 1.0f;
    if (!scene.bounds.empty())
        extent = std::max({extent, glm::length(scene.bounds.min), glm::length(scene.bounds.max)});
    s.extent = extent;
    return s;
}

SceneChanges sceneChanges(const SceneSnapshot& before, const SceneSnapshot& after) {
    SceneChanges c;
    if (before.staticHash != after.staticHash || before.instanceMeshes != after.instanceMeshes ||
        before.meshBounds.size() != after.meshBounds.size() || before.lights.size() != after.lights.size()) {
        c.unknown = true;
        return c;
    }
    for (size_t i = 0; i < after.instanceTransforms.size(); ++i) {
        if (before.instanceTransforms[i] == after.instanceTransforms[i]) continue;
        const Bounds& object = after.meshBounds[after.instanceMeshes[i]];
        for (const glm::mat4& transform : {before.instanceTransforms[i], after.instanceTransforms[i]}) {
            Bounds region = transformedBounds(object, transform);
            if (region.empty()) continue;
            const float extent = std::max({after.extent, glm::length(region.min), glm::length(region.max)});
            const float margin = regionMargin(extent);
            region.min -= glm::vec3(margin);
            region.max += glm::vec3(margin);
            c.regions.push_back(region);
        }
    }
    for (size_t i = 0; i < after.lights.size(); ++i)
        if (std::memcmp(&before.lights[i], &after.lights[i], sizeof(gpu::GpuLight)) != 0)
            c.lights.push_back(static_cast<uint32_t>(i));
    return c;
}

std::vector<Bounds> mergeRegions(std::vector<Bounds> regions, size_t count) {
    count = std::max<size_t>(count, 1);
    if (regions.size() <= count) return regions;
    // Sorted along the axis their centres spread most, then runs of neighbours joined: the union
    // of each run bounds its regions (conservative), and neighbours keep the unions small.
    Bounds centres;
    for (const Bounds& r : regions) centres.grow(r.center());
    const glm::vec3 spread = centres.extent();
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
    std::sort(regions.begin(), regions.end(),
              [axis](const Bounds& a, const Bounds& b) { return a.center()[axis] < b.center()[axis]; });
    std::vector<Bounds> merged(count);
    for (size_t i = 0; i < regions.size(); ++i) merged[i * count / regions.size()].grow(regions[i]);
    return merged;
}

}  // namespace vkp
