// Path tracing pass (shaders/pathtrace.comp; guided_pathtrace.comp with a guiding photon grid,
// guided_cached_pathtrace.comp with a guiding cache at bindings 11 and 12): reads the scene
// buffers (and the guide), adds samples to the film (vec4 per pixel: RGB sum and sample count)
// and counts dropped non-finite samples. With the kPathFlagRaster* flags it also reads the raster
// direct light (binding 10, vec4 per pixel, raster_direct_pass.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "shared/gpu_types.glsl"
#include "shared/guiding.glsl"
#include "vk/buffer.h"
#include "vk/compute_kernel.h"

namespace vkp {

class PathTracePass {
public:
    // `rasterDirect`: the raster pass's direct light (any buffer when the flags do not ask for it);
    // `shader` and the buffers it reads after it (a guided variant's guide).
    PathTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                  const vk::Buffer& counters, const vk::Buffer& rasterDirect,
                  const std::string& shader = "pathtrace.comp", const std::vector<const vk::Buffer*>& guide = {});

    void record(VkCommandBuffer cmd, const gpu::PathTraceParams& params) const;
    void record(VkCommandBuffer cmd, const gpu::PathTraceParams& params, const gpu::GuideParams& guide) const;

private:
    vk::ComputeKernel m_kernel;
};

}  // namespace vkp
