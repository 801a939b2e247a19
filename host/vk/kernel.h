// A compute kernel typed by its interface K, a descriptor from shaders/shared/kernels/ (e.g.
// gpu::GridCountKernel): the shader, the number of storage buffers, the push-constant type and
// the workgroup size all come from K, so the host states none of them itself, and dispatches are
// sized in items (one invocation each). Creating it checks K against the shader's SPIR-V.
#pragma once

#include <cstdint>
#include <vector>

#include "vk/compute_kernel.h"
#include "vk/kernel_interface.h"

namespace vkp::vk {

template <typename K> class Kernel {
public:
    using Push = typename K::Push;

    explicit Kernel(Context& context) : m_kernel(context, interfaceOf<K>()) {}

    // Points binding `binding` at `buffer` (whole range).
    void bind(uint32_t binding, const Buffer& buffer) { m_kernel.bind(binding, buffer); }
    // Points bindings first, first + 1, ... at `buffers`.
    void bind(const std::vector<const Buffer*>& buffers, uint32_t first = 0) { m_kernel.bind(buffers, first); }
    // Points the buffers as above and the scene textures (kernels that read them).
    void bind(const KernelBindings& bindings, uint32_t first = 0) { m_kernel.bind(bindings, first); }

    // Records one invocation per item, in workgroups of K::kGroupSize (none when items is 0).
    // More workgroups than the device dispatches in x need K::kRowsOfGroups (the kernel numbers
    // its items with itemIndex(), shaders/common/item_index.glsl): they go as rows of workgroups.
    void record(VkCommandBuffer cmd, uint64_t items, const Push& push) const {
        m_kernel.record(cmd, groupCount(items, K::kGroupSize), &push, sizeof(Push), 0, kRows);
    }
    // Records the items of `range` among `total` (a window of pixels; see ItemRange).
    void record(VkCommandBuffer cmd, ItemRange range, uint64_t total, const Push& push) const {
        m_kernel.record(cmd, range, total, push);
    }

private:
    static constexpr bool kRows = requires { K::kRowsOfGroups; };
    ComputeKernel m_kernel;
};

}  // namespace vkp::vk
