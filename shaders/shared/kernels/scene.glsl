// The scene's storage buffers, bound at the same bindings of every kernel that reads the scene
// (shaders/scene_access.glsl declares them; host/gpu_scene/scene_buffers.h uploads them). A
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
const uint kSceneTexelsBinding = 7u;     // uint: RGBA8 texels of all textures
// GpuInstanceHeader, then GpuInstance[] (two-level BVH, docs/bvh.md). coordination.md: binding 9
// once the material tables take 8.
const uint kSceneInstancesBinding = 8u;
const uint kSceneBindingCount = 9u;

SHARED_END
#endif
