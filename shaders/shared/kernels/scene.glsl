// The scene's storage buffers, bound at the same bindings of every kernel that reads the scene
// (shaders/render/scene_access.glsl declares them; host/gpu_scene/scene_buffers.h uploads them). A
// kernel's own buffers follow from kSceneBindingCount on.
#ifndef VKP_KERNELS_SCENE_GLSL
#define VKP_KERNELS_SCENE_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kSceneTrianglesBinding = 0u;  // GpuTriangle, BVH order
const uint kSceneBvhNodesBinding = 1u;   // GpuBvhNode
const uint kSceneShadingBinding = 2u;    // GpuTriangleShading, BVH order
const uint kSceneMaterialsBinding = 3u;  // GpuMaterial
const uint kSceneLightsBinding = 4u;     // GpuLight
const uint kSceneLightCdfBinding = 5u;   // float: inclusive prefix sums of the selection pdf
const uint kSceneTexturesBinding = 6u;   // GpuTexture
const uint kSceneTexelsBinding = 7u;     // float: the environment map (textures are images: below)
const uint kSceneTablesBinding = 8u;     // float: the BSDF's albedo tables (shared/bsdf_tables.glsl kBsdfTables)
const uint kSceneInstancesBinding = 9u;  // GpuInstanceHeader, then GpuInstance[] (two-level BVH, docs/bvh.md)
const uint kSceneBindingCount = 10u;

// Specialization constants (bool, default true) of kernels that trace rays, set from the bound
// scene (vk::SceneSpecialization, docs/bvh.md "Specialized kernels"): false compiles the
// instance code or the alpha test out of the traversal, or the texture lookup out of the shading;
// the light sampler's mode compiles the other modes out of next-event estimation.
const uint kSceneHasInstancesId = 0u;
const uint kSceneHasAlphaTestId = 1u;
const uint kSceneHasTexturesId = 2u;
const uint kSceneLightSamplerId = 3u;  // uint: kLightSamplerPower/Bvh/Photon, or kLightSamplerAny
// bool, default false: the traversal reads nodes and triangles through the texel-buffer views of
// set kSceneGeometrySet instead of the storage buffers (shaders/render/scene_geometry.glsl).
const uint kSceneBvhTexelsId = 4u;

// The textures: one RGBA8 2-D array image (host/gpu_scene/texture_atlas.h), read with texelFetch
// through two views, in a descriptor set of their own (set 1 holds the termination counters).
const uint kSceneTextureSet = 2u;
const uint kSceneTextureUnormBinding = 0u;  // sampler2DArray, R8G8B8A8_UNORM view
const uint kSceneTextureSrgbBinding = 1u;   // sampler2DArray, R8G8B8A8_SRGB view (decoded on read)

// The BVH nodes and triangles again (the same buffers as bindings kSceneBvhNodesBinding and
// kSceneTrianglesBinding), as R32G32B32A32_UINT uniform texel buffers: two texels per GpuBvhNode,
// three per GpuTriangle. lavapipe reads a storage buffer at a per-lane address one lane and one
// 32-bit word at a time (a scalar loop with a bounds check per word); a texel fetch is a vector
// gather (docs/bvh.md "Texel-buffer reads").
const uint kSceneGeometrySet = 3u;
const uint kSceneNodeTexelsBinding = 0u;      // usamplerBuffer over the GpuBvhNode buffer
const uint kSceneTriangleTexelsBinding = 1u;  // usamplerBuffer over the GpuTriangle buffer

SHARED_END
#endif
