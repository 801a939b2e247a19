// Importon tracing pass (shaders/photon/importon_trace.comp): reads the scene buffers, writes importon
// records (GpuPhoton layout, shared/importance.glsl) into fixed per-path slots.
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "shared/importance.glsl"
#include "shared/kernels/importons.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class ImportonTracePass {
public:
    // `importons`: params.pathCount * params.maxDeposits slots, zeroed by the caller before.
    ImportonTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& importons);

    void record(VkCommandBuffer cmd, const gpu::ImportonTraceParams& params) const;

private:
    vk::Kernel<gpu::ImportonTraceKernel> m_kernel;
};

}  // namespace vkp
