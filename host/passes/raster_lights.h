// The lights the raster pass covers, as GpuLight records: point, spot and directional lights as
// they are, and every emissive triangle as `areaSamples` point samples (kLightAreaSample) spread
// over it by a Hammersley set (stratified in both dimensions), each carrying 1/areaSamples of the
// triangle's emission. With areaSamples = 0 the emissive triangles stay with the compute passes.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "shared/shadow_volume.glsl"

namespace vkp {

// `keep` (per light of arrays.lights, may be null): lights marked false are left out (lights/light_reach.h).
std::vector<gpu::GpuLight> buildRasterLights(const SceneArrays& arrays, uint32_t areaSamples,
                                             const std::vector<bool>* keep = nullptr);

}  // namespace vkp
