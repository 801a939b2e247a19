// Path tracing pass (shaders/render/pathtrace.comp; guided_pathtrace.comp with a guiding photon grid,
// guided_cached_pathtrace.comp with a guiding cache): reads the scene buffers (and the guide),
// adds samples to the film (vec4 per pixel: RGB sum and sample count) and counts dropped
// non-finite samples and traced rays. With the kPathFlagRaster* flags it also reads the raster
// direct light (vec4 per pixel, raster_direct_pass.h). Bindings: shared/kernels/path_trace.glsl.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "shared/gpu_types.glsl"
#include "shared/guiding.glsl"
#include "shared/kernels/path_trace.glsl"
#include "vk/buffer.h"
#include "vk/compute_kernel.h"

namespace vkp {

// The counter buffer's slots (kPathTraceCounter*), summed over the dispatches since it was zeroed.
struct PathTraceCounters {
    uint64_t nonFiniteSamples = 0;  // dropped
    uint64_t segments = 0;          // rays traced from camera-path vertices
};

class PathTracePass {
public:
    // `rasterDirect`: the raster pass's direct light (any buffer when the flags do not ask for it);
    // `shader` (one of the kernels of shared/kernels/path_trace.glsl) and the buffers it reads
    // from kPathTraceGuideBinding on (a guided variant's guide).
    PathTracePass(vk::Context& context, const SceneBuffers& scene, const vk::Buffer& film,
                  const vk::Buffer& counters, const vk::Buffer& rasterDirect,
                  const std::string& shader = gpu::PathTraceKernel::kShader,
                  const std::vector<const vk::Buffer*>& guide = {});

    // `pixels`: the window of pixels to compute (--tile, --crop), all by default.
    void record(VkCommandBuffer cmd, const gpu::PathTraceParams& params, vk::ItemRange pixels = {}) const;
    void record(VkCommandBuffer cmd, const gpu::PathTraceParams& params, const gpu::GuideParams& guide,
                vk::ItemRange pixels = {}) const;

    // Reads the counter buffer back (after the submission that wrote it has completed).
    static PathTraceCounters readCounters(const vk::Buffer& counters);

private:
    vk::ComputeKernel m_kernel;  // the interface of `shader`, chosen at run time
};

}  // namespace vkp
