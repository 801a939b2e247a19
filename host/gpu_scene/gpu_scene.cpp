#include "gpu_scene/gpu_scene.h"

#include "util/stopwatch.h"

namespace vkp {

GpuScene::GpuScene(vk::Context& context, const Scene& scene)
    : m_context(context), m_scene(scene), m_arrays(buildSceneArrays(scene)), m_buffers([&] {
          const auto start = Clock::now();
          SceneBuffers buffers(context, m_arrays);
          m_uploadSeconds = secondsSince(start);
          return buffers;
      }()) {}

}  // namespace vkp
