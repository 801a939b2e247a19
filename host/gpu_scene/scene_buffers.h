// The scene on the GPU: BVH-ordered triangles, BVH nodes, shading attributes, materials, lights
// with their selection CDF, and textures. Bound at the bindings shared/kernels/scene.glsl names
// (0..7) of every kernel that reads the scene (shaders/render/scene_access.glsl declares them).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <memory>

#include "bvh/scene_bvh.h"
#include "lights/light_tree.h"
#include "gpu_scene/texture_atlas.h"
#include "scene/scene.h"
#include "shared/gpu_types.glsl"
#include "shared/kernels/scene.glsl"
#include "vk/buffer.h"
#include "vk/buffer_view.h"
#include "vk/compute_kernel.h"
#include "vk/texture_array.h"

namespace vkp {

// Host-side arrays in GPU layout, built without a device so they can be tested on their own.
struct SceneArrays {
    std::vector<gpu::GpuTriangle> triangles;        // static (BVH order), then each mesh's (docs/bvh.md)
    std::vector<gpu::GpuBvhNode> nodes;             // static tree at 0, meshes' trees, top level
    std::vector<gpu::GpuTriangleShading> shading;   // as triangles
    std::vector<gpu::GpuMaterial> materials;
    std::vector<gpu::GpuLight> lights;
    std::vector<float> lightCdf;                    // inclusive prefix sums of selectPdf, last = 1; then
                                                    // the selection data (shared/light_selection.glsl)
    std::vector<gpu::GpuTexture> textures;
    TextureAtlas textureAtlas;                      // the textures' texels (texture_atlas.h)
    std::vector<float> environment;                 // the environment map's floats (binding kSceneTexelsBinding)
    double totalLightPower = 0.0;                   // watts, sum over all lights
    double bvhBuildSeconds = 0.0;
    LightSampling lightSampling;                    // what lightCdf's header selects (--light-sampler)
    LightTreeStats lightTree;                       // the selection data after the CDF
    InstanceLevel topLevel;                         // instances, their header (binding kSceneInstancesBinding)
    std::vector<double> lightPower;                 // per light: its selection weight (what lightCdf sums)

    // The traversal's view (shared/bvh_traverse.glsl) for host-side rays.
    gpu::BvhArrays bvhArrays() const { return {nodes, triangles, topLevel.instances, topLevel.header}; }
    // The instance buffer's contents: the header, then the instances.
    std::vector<uint8_t> instanceBytes() const;
};

// Every triangle in world space, in hit-id order (static ones, then each instance's): what the
// raster pass draws. Without instances, `triangles` itself.
std::vector<gpu::GpuTriangle> worldTriangles(const SceneArrays& arrays);

// Builds the BVH and the GPU arrays. Lights are selected for next-event estimation in proportion
// to their emitted power (emissive triangles: pi * luminance(Le) * area, twice if double-sided,
// Le averaged over the emissive texture's texels the triangle reads (textured_emission.h);
// point/spot: 4 pi * luminance(I); directional: luminance(E) * pi * r^2 of the scene's bounding
// sphere) by default; `sampling` picks the light-selection mode next-event estimation uses and how
// it samples triangles (lights/light_tree.h); the light BVH is built for every mode. Each emissive triangle's
// GpuTriangle.v1.w holds its light index (as a float), -1 elsewhere.
// Textures are packed into an atlas within `textureLimits` (downscaled where needed: the
// atlas's `downscaled` lists them; callers warn).
SceneArrays buildSceneArrays(const Scene& scene, LightSampling sampling = {}, const TextureLimits& textureLimits = {});

// The limits of `context`'s device for the texture atlas, with the user's --max-texture-size.
TextureLimits deviceTextureLimits(const vk::Context& context, uint32_t maxTextureSize = 0);

// The most triangles a device can hold: its largest per-triangle buffer (the shading
// attributes) within maxStorageBufferRange; the BVH needs fewer bytes per triangle.
inline uint64_t deviceTriangleLimit(uint64_t maxStorageBufferRange) {
    return maxStorageBufferRange / std::max(sizeof(gpu::GpuTriangle), sizeof(gpu::GpuTriangleShading));
}

// The BSDF's albedo tables (shared/bsdf_tables.glsl), uploaded once per scene (scene binding
// kSceneTablesBinding; test kernels that evaluate the BSDF bind it too).
vk::Buffer makeBsdfTablesBuffer(vk::Context& context);

gpu::GpuCamera makeGpuCamera(const Camera& camera, uint32_t width, uint32_t height);

// What the scene lets its kernels compile out (vk::SceneSpecialization): no instances, no
// alpha-tested triangle (GpuTriangle v0.w, set from the materials above), no texture; and the
// light sampler its selection data names.
vk::SceneSpecialization sceneSpecialization(const SceneArrays& arrays);

class SceneBuffers {
public:
    SceneBuffers(vk::Context& context, const SceneArrays& arrays);

    // The scene buffers in binding order (kSceneBindingCount of them, from binding 0), the
    // texture array (set gpu::kSceneTextureSet), the BVH's texel-buffer views (set
    // gpu::kSceneGeometrySet) and the scene's specialization (kernels that trace rays switch to
    // the pipeline compiled for it; bvhTexels when the device's views cover the whole BVH).
    vk::KernelBindings bindings() const;
    uint32_t lightCount() const { return m_lightCount; }
    // Uploads new light-selection data (the CDF, then shared/light_selection.glsl's layout): into
    // the buffer in place when it fits (kernels that bound the scene keep seeing it; returns
    // true), else into a new buffer of twice the data's size (kernels must bind the scene again;
    // returns false). Record no kernel using the scene meanwhile.
    bool replaceLightSelection(vk::Context& context, const std::vector<float>& data);
    uint64_t bytes() const;
    // Uploads the arrays' instances and top-level nodes after updateInstances (per frame): the
    // rest of the scene stays as uploaded. Record no kernel using the scene meanwhile.
    void updateInstances(const SceneArrays& arrays);
    // Uploads the arrays' lights and light-selection data in place (per frame, moving punctual
    // lights): the lights must keep their size, the selection data must fit its buffer. Record no
    // kernel using the scene meanwhile.
    void updateLights(const SceneArrays& arrays);

private:
    vk::Buffer m_triangles;
    vk::Buffer m_nodes;
    vk::Buffer m_shading;
    vk::Buffer m_materials;
    vk::Buffer m_lights;
    vk::Buffer m_lightCdf;
    vk::Buffer m_textures;
    vk::Buffer m_texels;                             // the environment map's floats
    vk::Buffer m_tables;  // the BSDF's albedo tables (shared/bsdf_tables.glsl kBsdfTables), binding kSceneTablesBinding
    vk::Buffer m_instances;                          // GpuInstanceHeader + GpuInstance[] (docs/bvh.md)
    std::unique_ptr<vk::TextureArray> m_textureArray;
    vk::BvhTexelViews m_bvhTexels;  // m_nodes and m_triangles as texel buffers (shaders/render/scene_geometry.glsl)
    // Throws std::logic_error when `selection` names another light sampler than the one the
    // scene's kernels are specialized for.
    void checkLightSampler(const std::vector<float>& selection) const;

    uint32_t m_lightCount = 0;
    vk::SceneSpecialization m_specialization;
};

}  // namespace vkp
