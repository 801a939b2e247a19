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

#include "shared/gpu_types.glsl"
#include "shared/light_tree.glsl"

namespace vkp {

enum class LightSampler { Power, Bvh, Photon };
// How an emissive triangle is sampled once chosen: by the solid angle it subtends (area where that
// is tiny or nearly a hemisphere), or by area only (the behaviour before solid-angle sampling).
enum class TriangleSampling { SolidAngle, Area };

// --light-sampler, --triangle-sampling and the photon light cells' flags (render/light_cells.h).
struct LightSampling {
    LightSampler sampler = LightSampler::Power;
    TriangleSampling triangles = TriangleSampling::SolidAngle;
    uint32_t cellPhotons = 200000;  // --light-photons: photon paths whose primary hits fill the cells
    uint32_t cellK = 8;             // --light-cell-k: candidates per cell at most
    float cellFloor = 0.25f;        // --light-cell-floor: probability of the light BVH's choice
    float cellSize = 0.0f;          // --light-cell-size (m); 0: the scene's largest extent / 40

    // Throws InputError naming the flag of a value out of range.
    void check() const;
};

// "power", "bvh", "photon".
std::string_view lightSamplerName(LightSampler sampler);
// Throws InputError naming --light-sampler for an unknown name.
LightSampler parseLightSampler(std::string_view name);

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
