// Path tracing pass (shaders/pathtrace.comp): reads the scene buffers, adds samples to the film
// (vec4 per pixel: RGB sum and sample count) and counts dropped non-finite samples. With the
// kPathFlagRaster* flags it also reads the raster direct light (vec4 per pixel, raster_direct_pass.h).
#pragma once

#include <cstdint>

#include "passes/scene_buffers.h"
#include "shared/gpu_types.glsl"
#include "vk/buffer.h"
#include "vk/compute_kernel.h"

namespace vkp {

class PathTracePass {
public:
    PathTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                  const vk::Buffer& counters, const vk::Buffer& rasterDirect);

    void record(VkCommandBuffer cmd, const gpu::PathTraceParams& params) const;

private:
    vk::ComputeKernel m_kernel;
};

}  // namespace vkp
