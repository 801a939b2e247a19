// A compute shader compiled into a pipeline with its layouts, for one kernel interface. Creating
// it checks the shader's SPIR-V against the interface (shader_reflection.h). lavapipe compiles
// SPIR-V to machine code when a pipeline is created, a second or more for the large kernels, so
// the context keeps each pipeline once made (ComputePipelineCache) and every ComputeKernel of the
// same interface (each render, each frame, each integrator) shares it; a kernel owns only its
// descriptor sets.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>

#include <vulkan/vulkan.h>

#include "vk/kernel_interface.h"

namespace vkp::vk {

class Context;

// Whether SPIR-V declares the scene's specialization constants (gpu::kSceneHasInstancesId,
// kSceneHasAlphaTestId, kSceneHasTexturesId, kSceneLightSamplerId, kSceneBvhTexelsId): kernels that trace rays
// (shared/bvh_traverse.glsl), read the scene's textures or select lights (scene_access.glsl).
bool usesSceneSpecialization(std::span<const uint32_t> spirv);
// Whether SPIR-V declares gpu::kSingleSegmentId: kernels that bind segmented arrays
// (shaders/common/segmented_arrays.glsl); vk::ComputeKernel picks that form per dispatch.
bool usesSingleSegmentSpecialization(std::span<const uint32_t> spirv);

class ComputePipeline {
public:
    // Throws RuntimeError when the shader's SPIR-V does not declare what `interface` says. The
    // pipeline is compiled on first use (pipeline()), with `scene`'s specialization constants and
    // gpu::kSingleSegmentId = singleSegment (every segmented array it binds has one segment).
    ComputePipeline(const Context& context, const KernelInterface& interface, SceneSpecialization scene = {},
                    bool singleSegment = false);
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    // Compiles on the first call (a kernel that is bound to a scene before its first dispatch
    // never compiles the unspecialized form). Thread-safe.
    VkPipeline pipeline() const;
    VkPipelineLayout layout() const { return m_pipelineLayout; }
    // Set 0: the storage buffers at bindings 0 .. bindingCount - 1.
    VkDescriptorSetLayout bufferSetLayout() const { return m_setLayout; }
    // Set gpu::kTerminationSet, or VK_NULL_HANDLE when the shader declares no termination counters.
    VkDescriptorSetLayout terminationSetLayout() const { return m_terminationLayout; }
    // Set gpu::kSceneTextureSet, or VK_NULL_HANDLE when the shader reads no scene textures.
    VkDescriptorSetLayout textureSetLayout() const { return m_textureLayout; }
    // Set gpu::kSceneGeometrySet, or VK_NULL_HANDLE when the shader declares no BVH texel buffers.
    VkDescriptorSetLayout geometrySetLayout() const { return m_geometryLayout; }

private:
    VkDevice m_device = VK_NULL_HANDLE;
    VkShaderModule m_module = VK_NULL_HANDLE;
    VkDescriptorSetLayout m_setLayout = VK_NULL_HANDLE;
    VkDescriptorSetLayout m_terminationLayout = VK_NULL_HANDLE;
    VkDescriptorSetLayout m_emptyLayout = VK_NULL_HANDLE;  // sets left out below a declared one
    VkDescriptorSetLayout m_textureLayout = VK_NULL_HANDLE;
    VkDescriptorSetLayout m_geometryLayout = VK_NULL_HANDLE;
    VkPipelineLayout m_pipelineLayout = VK_NULL_HANDLE;
    std::string m_name;
    SceneSpecialization m_scene;
    bool m_singleSegment = false;
    mutable std::once_flag m_compiled;
    mutable VkPipeline m_pipeline = VK_NULL_HANDLE;
};

// The pipelines a context has made, by interface; they live as long as the cache (the context's
// lifetime). Thread-safe.
class ComputePipelineCache {
public:
    // One pipeline per interface and, for shaders that use them, per scene specialization and
    // per segment specialization (one segment or any).
    const ComputePipeline& get(const Context& context, const KernelInterface& interface,
                               SceneSpecialization scene = {}, bool singleSegment = false);
    size_t size() const;
    void clear();

private:
    mutable std::mutex m_mutex;
    std::map<std::string, std::unique_ptr<ComputePipeline>> m_pipelines;
};

}  // namespace vkp::vk
