// One compute shader with its pipeline (compiled once per context: compute_pipeline.h), a descriptor set of storage buffers (binding i = the i-th
// buffer) and a push-constant block, as its KernelInterface says; creating it checks that the
// shader declares exactly that (shader_reflection.h). Recording binds, pushes and dispatches: no
// submit, no wait. Passes use the typed form, vk::Kernel<K> (kernel.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/compute_pipeline.h"
#include "vk/kernel_interface.h"

namespace vkp::vk {

class Buffer;
class Context;
class TextureArray;

// The scene's BVH nodes and triangles as uniform texel buffers (R32G32B32A32_UINT views of the
// storage buffers), set gpu::kSceneGeometrySet (shaders/render/scene_geometry.glsl).
struct SceneGeometryViews {
    VkBufferView nodes = VK_NULL_HANDLE;
    VkBufferView triangles = VK_NULL_HANDLE;
};

// What a resource owner binds to a kernel at once (SceneBuffers::bindings()): storage buffers at
// bindings first, first + 1, ... of set 0 and, for kernels that declare it, the texture array of
// set gpu::kSceneTextureSet and the BVH's texel-buffer views of set gpu::kSceneGeometrySet
// (kernels that declare neither ignore them).
// A scene's bindings also say what the scene lets the traversal leave out (`scene`): binding them
// switches a ray-tracing kernel to the pipeline specialized for it (compute_pipeline.h).
struct KernelBindings {
    std::vector<const Buffer*> buffers;
    const TextureArray* textures = nullptr;
    std::optional<SceneSpecialization> scene;
    const SceneGeometryViews* geometry = nullptr;
};

// Items first .. first + count - 1 of a dispatch (a window of pixels: --tile, --crop). Recorded
// as the workgroups that cover them (vkCmdDispatchBase), so gl_GlobalInvocationID is the item's
// index in the whole range and a kernel computes each item exactly as in a full dispatch; the
// groups' edges may add a few items before and after, which compute their own values.
struct ItemRange {
    uint64_t first = 0;
    uint64_t count = UINT64_MAX;  // the default: every item

    // This range within `total` items.
    ItemRange within(uint64_t total) const {
        const uint64_t begin = std::min(first, total);
        return {begin, std::min(count, total - begin)};
    }
};

class ComputeKernel {
public:
    // Throws RuntimeError when the shader's SPIR-V does not declare what `interface` says.
    ComputeKernel(Context& context, KernelInterface interface);
    ~ComputeKernel();
    ComputeKernel(const ComputeKernel&) = delete;
    ComputeKernel& operator=(const ComputeKernel&) = delete;

    // Points binding `binding` at `buffer` (whole range).
    void bind(uint32_t binding, const Buffer& buffer);
    // Points bindings first, first + 1, ... at `buffers`.
    void bind(const std::vector<const Buffer*>& buffers, uint32_t first = 0);
    // Points the buffers as above and, when the shader declares them, the scene textures; with
    // bindings.scene, later dispatches use the pipeline specialized for that scene.
    void bind(const KernelBindings& bindings, uint32_t first = 0);
    // Points set gpu::kSceneTextureSet at `textures` (ignored when the shader declares no textures).
    void bind(const TextureArray& textures);
    // Points set gpu::kSceneGeometrySet at `views` (ignored when the shader declares none).
    void bind(const SceneGeometryViews& views);

    // Dispatches `groups` 1-D workgroups, from workgroup `firstGroup` on, after pushing
    // `pushBytes` of push constants. Past maxComputeWorkGroupCount[0] workgroups, a kernel whose
    // items are numbered by itemIndex() (`rows`) gets rows of kRowGroups workgroups; any other
    // throws.
    void record(VkCommandBuffer cmd, uint64_t groups, const void* push, uint32_t pushBytes,
                uint32_t firstGroup = 0, bool rows = false) const;
    static constexpr uint32_t kRowGroups = 32768;  // workgroups per row (shaders/common/item_index.glsl)
    template <typename Push> void record(VkCommandBuffer cmd, uint32_t groups, const Push& push) const {
        record(cmd, groups, &push, sizeof(Push));
    }
    // Dispatches the workgroups that cover `items` of `total` (one invocation per item).
    template <typename Push>
    void record(VkCommandBuffer cmd, ItemRange items, uint64_t total, const Push& push) const {
        const ItemRange r = items.within(total);
        const uint64_t firstGroup = r.first / groupSize();
        const uint64_t endGroup = (r.first + r.count + groupSize() - 1) / groupSize();
        record(cmd, static_cast<uint32_t>(endGroup - firstGroup), &push, sizeof(Push),
               static_cast<uint32_t>(firstGroup));
    }

    const std::string& name() const { return m_interface.shader; }
    uint32_t groupSize() const { return m_interface.groupSize; }

private:
    Context& m_context;
    KernelInterface m_interface;
    std::vector<VkBuffer> m_bound;  // per binding; VK_NULL_HANDLE until bound
    // The context's, shared by every kernel of this interface (and scene specialization); the
    // descriptor sets, allocated with the first one's layouts, fit all of them (identical layouts).
    const ComputePipeline* m_pipeline;
    // The same compiled for segmented arrays of one segment (gpu::kSingleSegmentId), used by the
    // dispatches whose bound segmented arrays all have one; null when the shader binds none.
    const ComputePipeline* m_singleSegmentPipeline = nullptr;
    // The pipeline for a dispatch now: m_singleSegmentPipeline when every segmented array bound
    // has at most one segment (vk::SegmentedBuffer::segmentsAddressedBy), else m_pipeline.
    const ComputePipeline& dispatchPipeline() const;
    VkDescriptorPool m_pool = VK_NULL_HANDLE;
    VkDescriptorSet m_set = VK_NULL_HANDLE;
    // The shared silent-termination counters (set gpu::kTerminationSet), when the shader declares them.
    VkDescriptorSet m_terminationSet = VK_NULL_HANDLE;
    // The scene textures (set gpu::kSceneTextureSet), when the shader declares them.
    VkDescriptorSet m_textureSet = VK_NULL_HANDLE;
    bool m_texturesBound = false;
    // The BVH's texel-buffer views (set gpu::kSceneGeometrySet), when the shader declares them.
    VkDescriptorSet m_geometrySet = VK_NULL_HANDLE;
    bool m_geometryBound = false;
};

// Makes compute-shader writes visible to later compute reads and transfers.
void computeBarrier(VkCommandBuffer cmd);
// Makes compute writes visible to the host after the submission's fence (for mapped buffers).
void computeToHostBarrier(VkCommandBuffer cmd);
// Makes transfer writes (fills, copies) visible to compute shaders.
void transferToComputeBarrier(VkCommandBuffer cmd);
// Makes compute and transfer writes visible to later transfers (a copy after a fill or a kernel).
void transferBarrier(VkCommandBuffer cmd);

inline uint32_t groupCount(uint64_t items, uint32_t groupSize) {
    return static_cast<uint32_t>((items + groupSize - 1) / groupSize);
}

}  // namespace vkp::vk
