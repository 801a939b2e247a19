#include "gpu_scene/gpu_scene.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "shared/light_selection.glsl"
#include "util/printable.h"
#include "util/stopwatch.h"

namespace vkp {

namespace {
SceneArrays buildAndWarn(const vk::Context& context, const Scene& scene, LightSampling lightSampling) {
    SceneArrays arrays = buildSceneArrays(scene, lightSampling, deviceTextureLimits(context));
    for (const std::string& line : arrays.textureAtlas.downscaled)
        fmt::print(stderr, "warning: texture downscaled: {}\n", printable(line));
    return arrays;
}
}  // namespace

GpuScene::GpuScene(vk::Context& context, const Scene& scene, LightSampling lightSampling)
    : m_context(context), m_scene(scene), m_arrays(buildAndWarn(context, scene, lightSampling)),
      m_buffers([&] {
          const auto start = Clock::now();
          SceneBuffers buffers(context, m_arrays);
          m_uploadSeconds = secondsSince(start);
          return buffers;
      }()) {}

bool GpuScene::replaceLightSelection(std::vector<float> data) {
    m_arrays.lightCdf = std::move(data);
    return m_buffers.replaceLightSelection(m_context, m_arrays.lightCdf);
}

bool GpuScene::updatePunctualLights(const Scene& scene) {
    // buildSceneArrays's order: emissive triangles, then the punctual lights, then the environment.
    uint32_t first = 0;
    while (first < m_arrays.lights.size() && m_arrays.lights[first].type == gpu::kLightTriangle) ++first;
    if (first + scene.lights.size() > m_arrays.lights.size()) return false;
    std::vector<gpu::GpuLight> lights = m_arrays.lights;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const PunctualLight& l = scene.lights[i];
        gpu::GpuLight& g = lights[first + i];
        const uint32_t type = l.type == LightType::Point ? gpu::kLightPoint
                              : l.type == LightType::Spot ? gpu::kLightSpot
                                                          : gpu::kLightDirectional;
        if (g.type != type || g.intensity != l.intensity) return false;
        if (l.type == LightType::Spot) {  // the cone, as buildSceneArrays turns it into scale and offset
            const float cosOuter = std::cos(l.outerConeAngle);
            const float cosInner = std::cos(l.innerConeAngle);
            const float scale = 1.0f / std::max(0.001f, cosInner - cosOuter);
            if (g.spotScale != scale || g.spotOffset != -cosOuter * scale) return false;
        }
        g.position = l.position;
        g.direction = glm::normalize(l.direction);
    }
    if (lights.size() == m_arrays.lights.size() &&
        std::memcmp(lights.data(), m_arrays.lights.data(), lights.size() * sizeof(gpu::GpuLight)) == 0)
        return true;  // nothing moved
    const uint32_t count = static_cast<uint32_t>(lights.size());
    std::vector<float> selection(m_arrays.lightCdf.begin(), m_arrays.lightCdf.begin() + count);  // the CDF stays
    const LightTreeStats tree = appendLightSelection(
        selection, buildLightTree(lights, m_arrays.triangles, m_arrays.shading, m_arrays.materials, m_arrays.lightPower),
        count, m_arrays.lightSampling);
    // The tree must keep its size; a photon light-cell table after it (render/light_cells) is
    // replaced by the empty one appendLightSelection writes: the owner refreshes it
    // (Renderer::refreshLightCells), until then next-event estimation uses the light BVH alone.
    const uint32_t oldCells = gpu::lightCellsStart(gpu::LightSelectionArrays{m_arrays.lightCdf, {}}, count);
    if (gpu::lightCellsStart(gpu::LightSelectionArrays{selection, {}}, count) != oldCells) return false;
    m_arrays.lights = std::move(lights);
    m_arrays.lightCdf = std::move(selection);
    m_arrays.lightTree = tree;
    m_buffers.updateLights(m_arrays);
    return true;
}

void GpuScene::updateInstanceTransforms(std::span<const glm::mat4> transforms, TopLevelUpdate mode) {
    const auto start = Clock::now();
    updateInstances(m_arrays.nodes, m_arrays.topLevel, transforms, mode);
    m_arrays.bvhBuildSeconds = secondsSince(start);  // the last BVH work: the top level's update
    const auto uploadStart = Clock::now();
    m_buffers.updateInstances(m_arrays);
    m_uploadSeconds = secondsSince(uploadStart);
}

}  // namespace vkp
