// The load-time check of a compute kernel's interface: SPIR-V reflection (SPIRV-Cross's C API)
// reads the storage buffers a shader declares, the size of its push-constant block and its
// workgroup size, and compares them with what the host was told (kernel_interface.h), so a
// binding, push-constant struct or group size that drifted between the shader and the host fails
// when the kernel is created, with the shader's name and the difference, instead of reading
// garbage or tripping the validation layer later.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vk/kernel_interface.h"

namespace vkp::vk {

// What a compute shader's SPIR-V declares (all declared resources, used or not).
struct ShaderInterface {
    std::vector<uint32_t> storageBufferBindings;  // of set 0, ascending, without repeats
    std::vector<std::string> unbindable;          // resources a kernel cannot bind, described
    uint32_t pushConstantBytes = 0;               // declared size of the push-constant block; 0: none
    std::array<uint32_t, 3> localSize{};          // LocalSize (or LocalSizeId, evaluated)
    // Declares the shared silent-termination counters (set gpu::kTerminationSet, binding
    // gpu::kTerminationBinding), which vk::ComputeKernel binds to the context's buffer itself.
    bool terminationCounters = false;
    // Declares the scene's texture array (set gpu::kSceneTextureSet, bindings
    // kSceneTextureUnormBinding and kSceneTextureSrgbBinding: combined image samplers), which
    // vk::ComputeKernel binds from a vk::TextureArray.
    bool sceneTextures = false;
    // Declares the BVH's texel-buffer views (set gpu::kSceneGeometrySet, bindings
    // kSceneNodeTexelsBinding and kSceneTriangleTexelsBinding: uniform texel buffers), which
    // vk::ComputeKernel binds from a vk::SceneGeometryViews.
    bool sceneGeometry = false;
};

// Reflects `spirv` (a compute shader); throws RuntimeError naming `name` if it cannot be parsed.
ShaderInterface reflectComputeShader(std::string_view name, std::span<const uint32_t> spirv);

// Each way `shader` differs from what `host` was told, one phrase each ("the shader declares push
// constants of 24 bytes, the host pushes 20"); empty when they agree.
std::vector<std::string> interfaceMismatches(const KernelInterface& host, const ShaderInterface& shader);

// Throws RuntimeError "<shader>: <difference>; <difference>" when the SPIR-V `spirv` of
// host.shader does not declare exactly what `host` says; else returns what it declares.
ShaderInterface checkKernelInterface(const KernelInterface& host, std::span<const uint32_t> spirv);

}  // namespace vkp::vk
