// What the host tells a compute kernel: its shader, the storage buffers it binds (bindings
// 0..bindingCount-1 of set 0), the bytes of push constants it pushes and the workgroup size it
// sizes dispatches by. interfaceOf<K>() takes them from a kernel's interface in
// shaders/shared/kernels/; the kernel checks them against the shader's SPIR-V when it is created
// (shader_reflection.h).
#pragma once

#include <cstdint>
#include <string>

namespace vkp::vk {

struct KernelInterface {
    std::string shader;          // file name, e.g. "grid_count.comp"
    uint32_t bindingCount = 0;   // storage buffers at bindings 0 .. bindingCount - 1 of set 0
    uint32_t pushBytes = 0;      // push constants, from offset 0
    uint32_t groupSize = 1;      // local_size_x; local_size_y = local_size_z = 1
};

// The interface a kernel descriptor K declares: K::kShader, K::kBindingCount, K::Push,
// K::kGroupSize (e.g. gpu::GridCountKernel in shaders/shared/kernels/grid_build.glsl).
// What a scene lets the ray-tracing kernels leave out (shared/bvh_traverse.glsl): the
// specialization constants gpu::kSceneHasInstancesId, kSceneHasAlphaTestId, kSceneHasTexturesId
// and kSceneLightSamplerId. lavapipe runs both sides of every branch of a SIMD group, so code a scene
// never needs (the instance entry in each traversal step, the alpha test after each trace, the
// texture lookups of the shading, the light samplers the scene does not use) costs every ray
// unless it is compiled out (docs/bvh.md "Specialized kernels"). The default keeps everything:
// right for any scene. SceneBuffers::bindings() says what its scene has.
struct SceneSpecialization {
    bool instances = true;   // the scene has a top level (instanceCount > 0)
    bool alphaTest = true;   // some triangle is alpha-tested (GpuTriangle v0.w != 0)
    bool textures = true;    // some material has a texture (the scene's GpuTexture views)
    uint32_t lightSampler = 0xffffffffu;  // gpu::kLightSamplerPower/Bvh/Photon, or kLightSamplerAny (read the data)
    // The traversal reads nodes and triangles through the texel-buffer views of set
    // gpu::kSceneGeometrySet (shaders/render/scene_geometry.glsl); false: through the storage buffers.
    bool bvhTexels = false;
    bool operator==(const SceneSpecialization&) const = default;
};

template <typename K> KernelInterface interfaceOf() {
    return {K::kShader, K::kBindingCount, static_cast<uint32_t>(sizeof(typename K::Push)), K::kGroupSize};
}

}  // namespace vkp::vk
