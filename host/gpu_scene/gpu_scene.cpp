#include "gpu_scene/gpu_scene.h"

#include "util/stopwatch.h"

namespace vkp {

GpuScene::GpuScene(vk::Context& context, const Scene& scene, LightSampling lightSampling)
    : m_context(context), m_scene(scene), m_arrays(buildSceneArrays(scene, lightSampling)), m_buffers([&] {
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
