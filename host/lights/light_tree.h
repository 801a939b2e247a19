// The light-selection data next-event estimation reads (shared/light_selection.glsl): the mode,
// and for --light-sampler bvh a light BVH over emissive triangles and point/spot lights with
// orientation cones (Conty Estevez & Kulla 2018; pbrt-v4's BVHLightSampler). Appended to the
// power CDF in SceneArrays::lightCdf, so it travels in the same scene buffer.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lights/light_sampling.h"
#include "shared/gpu_types.glsl"
#include "shared/light_tree.glsl"

namespace vkp {

struct LightTreeStats {
    uint32_t nodes = 0;
    uint32_t treeLights = 0;      // lights in the tree (triangles, points, spots)
    uint32_t infiniteLights = 0;  // lights outside it (directional, ...)
    uint32_t depth = 0;           // deepest leaf (root: 0)
    uint64_t bytes = 0;           // the selection data after the CDF
};

// The nodes and each light's path from the root (bit d set: second child at depth d), before
// they are laid out in the selection buffer. `power[i]`: light i's selection weight (the power
// the CDF uses).
struct LightTree {
    std::vector<gpu::GpuLightNode> nodes;    // depth first, root at 0
    std::vector<uint32_t> trails;            // per light (0 for lights outside the tree)
    std::vector<uint32_t> infinite;          // lights outside the tree
    uint32_t depth = 0;
};
LightTree buildLightTree(std::span<const gpu::GpuLight> lights, std::span<const gpu::GpuTriangle> triangles,
                         std::span<const gpu::GpuTriangleShading> shading, std::span<const gpu::GpuMaterial> materials,
                         std::span<const double> power);

// Appends the header, trails, infinite list and nodes after the lightCount CDF entries of `data`.
LightTreeStats appendLightSelection(std::vector<float>& data, const LightTree& tree, uint32_t lightCount,
                                    LightSampling sampling);

}  // namespace vkp
