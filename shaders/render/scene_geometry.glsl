// The traversal's reads of BVH nodes and triangles (BVH_NODE_AT / BVH_TRIANGLE_AT for
// shared/bvh_traverse.glsl), for kernels that include scene_access.glsl.
//
// lavapipe (gallivm, Mesa 22.3) compiles a storage-buffer load at a per-lane address into a
// scalar loop over the 8 lanes with a bounds check and a branch per 32-bit word: a 32-byte node
// is 64 scalar loads for the group. A texel fetch from a uniform texel buffer is compiled as
// vector gathers. So kernels bound to a scene (SceneBuffers::bindings()) read the same buffers
// through R32G32B32A32_UINT views (set kSceneGeometrySet): bit-identical values, the same hits.
// kSceneBvhTexels (specialization constant, false by default and when the device's
// maxTexelBufferElements cannot cover the scene) keeps the storage-buffer reads.
// The including shader declares the storage buffers bvhNodes[] and triangles[] first (as
// scene_access.glsl and tests/shaders/bvh_trace_test.comp do).
#ifndef VKP_SCENE_GEOMETRY_GLSL
#define VKP_SCENE_GEOMETRY_GLSL
#include "shared/gpu_types.glsl"
#include "shared/kernels/scene.glsl"

layout(constant_id = kSceneBvhTexelsId) const bool kSceneBvhTexels = false;
layout(set = kSceneGeometrySet, binding = kSceneNodeTexelsBinding) uniform usamplerBuffer bvhNodeTexels;
layout(set = kSceneGeometrySet, binding = kSceneTriangleTexelsBinding) uniform usamplerBuffer triangleTexels;

GpuBvhNode bvhNodeAt(uint i) {
    if (!kSceneBvhTexels) return bvhNodes[i];
    uvec4 lo = texelFetch(bvhNodeTexels, int(2u * i));
    uvec4 hi = texelFetch(bvhNodeTexels, int(2u * i + 1u));
    GpuBvhNode node;
    node.boundsMin = uintBitsToFloat(lo.xyz);
    node.leftOrFirst = lo.w;
    node.boundsMax = uintBitsToFloat(hi.xyz);
    node.count = hi.w;
    return node;
}

GpuTriangle bvhTriangleAt(uint i) {
    if (!kSceneBvhTexels) return triangles[i];
    GpuTriangle triangle;
    triangle.v0 = uintBitsToFloat(texelFetch(triangleTexels, int(3u * i)));
    triangle.v1 = uintBitsToFloat(texelFetch(triangleTexels, int(3u * i + 1u)));
    triangle.v2 = uintBitsToFloat(texelFetch(triangleTexels, int(3u * i + 2u)));
    return triangle;
}

#define BVH_NODE_AT(i) bvhNodeAt(i)
#define BVH_TRIANGLE_AT(i) bvhTriangleAt(i)

#endif
