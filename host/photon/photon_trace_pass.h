// Photon tracing pass (shaders/photon/photon_trace.comp): reads the scene buffers, writes photon records
// into fixed per-path slots and adds to the photon counters (kPhotonCounter*,
// shared/kernels/photon_trace.glsl).
#pragma once

#include "gpu_scene/scene_buffers.h"
#include "shared/kernels/photon_trace.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

class PhotonTracePass {
public:
    // `pathList`: the Halton offsets PhotonTraceParams.pathList reads (at least 16 bytes);
    // `tracks`: the paths' tracks PhotonTraceParams.trackPaths writes (at least one GpuPathTrack).
    PhotonTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& photons,
                    const vk::Buffer& counters, const vk::Buffer& pathList, const vk::Buffer& tracks);

    void record(VkCommandBuffer cmd, const gpu::PhotonTraceParams& params) const;

private:
    vk::Kernel<gpu::PhotonTraceKernel> m_kernel;
};

}  // namespace vkp
