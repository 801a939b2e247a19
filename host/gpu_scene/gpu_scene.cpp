#include "gpu_scene/gpu_scene.h"

#include <cstdio>

#include <fmt/format.h>

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

void GpuScene::replaceLightSelection(std::vector<float> data) {
    m_arrays.lightCdf = std::move(data);
    m_buffers.replaceLightSelection(m_context, m_arrays.lightCdf);
}

void GpuScene::updateInstanceTransforms(std::span<const glm::mat4> transforms, TopLevelUpdate mode) {
    updateInstances(m_arrays.nodes, m_arrays.topLevel, transforms, mode);
    m_buffers.updateInstances(m_arrays);
}

}  // namespace vkp
