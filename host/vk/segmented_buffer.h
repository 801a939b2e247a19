// An array of fixed-size elements too large for one storage buffer: segments of 2^shift elements,
// each a buffer of its own, reached by shaders through a small table of their device addresses
// (shaders/common/segmented_arrays.glsl: element i lives at segment i >> shift, index i & mask). Kernels bind
// the table like any storage buffer; segments are allocated as the array grows (reserve), and the
// table, allocated once for the array's capacity, never moves, so bindings stay valid. Nothing
// but the allocation limits bounds the array: maxStorageBufferRange applies to the table only.
#pragma once

#include <algorithm>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vk/buffer.h"

namespace vkp::vk {

class SegmentedBuffer {
public:
    SegmentedBuffer() = default;
    ~SegmentedBuffer();
    SegmentedBuffer(SegmentedBuffer&& other) noexcept = default;
    SegmentedBuffer& operator=(SegmentedBuffer&& other) noexcept;
    // Up to `capacity` elements of `elementSize` bytes in segments of 2^segmentShift elements
    // (0: defaultSegmentShift). Nothing is allocated until reserve().
    SegmentedBuffer(Context& context, std::string name, uint32_t elementSize, uint64_t capacity,
                    uint32_t segmentShift = 0);

    // Makes elements [0, count) addressable (count is clamped to the capacity): allocates the
    // missing segments, zero-filled, and rewrites the table. The last segment holds about what
    // was reserved (it grows by x1.5 steps, its elements copied), so memory follows the count;
    // call it between submissions, never while a recorded dispatch that binds the array waits. Throws RuntimeError (exit 1) when the
    // device cannot hold them.
    void reserve(uint64_t count);

    const Buffer& table() const { return m_table; }  // bind this
    uint64_t capacity() const { return m_capacity; }
    uint32_t elementSize() const { return m_elementSize; }
    uint64_t allocated() const { return m_allocated; }  // elements addressable
    uint32_t segmentShift() const { return m_shift; }
    size_t segmentCount() const { return m_segments.size(); }
    uint64_t bytes() const;  // device memory of the allocated segments (the table aside)

    void fillZero(VkCommandBuffer cmd) const;  // every allocated segment
    // Elements [first, first + count) to or from the host (within allocated()).
    void download(void* data, uint64_t first, uint64_t count) const;
    void upload(const void* data, uint64_t first, uint64_t count);
    template <typename T> std::vector<T> download(uint64_t count) const {
        std::vector<T> out(count);
        download(out.data(), 0, count);
        return out;
    }

    // Device copies between a plain buffer and elements of the array: elements [first, first +
    // count) and the bytes from bufferOffset in the buffer. Recorded as one vkCmdCopyBuffer per
    // segment touched (the runs split at segment ends); the caller places the barriers.
    struct ElementCopy {
        VkDeviceSize bufferOffset;
        uint64_t first;
        uint64_t count;
    };
    void recordCopyFrom(VkCommandBuffer cmd, const Buffer& src, std::span<const ElementCopy> copies) const;
    void recordCopyTo(VkCommandBuffer cmd, const Buffer& dst, std::span<const ElementCopy> copies) const;

    // The segments that `table` addresses when it is a live segmented array's table (bound by a
    // kernel as its storage buffer), nullopt for any other buffer. vk::ComputeKernel asks this at
    // each dispatch: kernels whose segmented arrays all have one segment run the pipeline compiled
    // for that (gpu::kSingleSegmentId), which indexes segment 0 without the table's shift and mask.
    static std::optional<size_t> segmentsAddressedBy(VkBuffer table);

    // The largest power of two of elements whose segment stays within 128 MiB and the device's
    // allocation limits (a segment is also the granularity of growth).
    static uint32_t defaultSegmentShift(const Context& context, uint32_t elementSize);

private:
    void writeTable();
    void recordCopies(VkCommandBuffer cmd, const Buffer& buffer, std::span<const ElementCopy> copies, bool intoArray) const;
    uint64_t segmentElements(size_t segment) const;
    // Calls run(segment, offset in it, element count, elements done before) for each segment's
    // part of the elements [first, first + count).
    template <typename Run> void forEachRun(uint64_t first, uint64_t count, Run run) const {
        uint64_t done = 0;
        while (count > 0) {
            const size_t segment = first >> m_shift;
            const uint64_t offset = first - (uint64_t(segment) << m_shift);
            const uint64_t n = std::min(count, segmentElements(segment) - offset);
            run(segment, offset, n, done);
            done += n;
            first += n;
            count -= n;
        }
    }

    Context* m_context = nullptr;
    std::string m_name;
    uint32_t m_elementSize = 0;
    uint64_t m_capacity = 0;
    uint32_t m_shift = 0;
    uint64_t m_allocated = 0;
    Buffer m_table;
    std::vector<Buffer> m_segments;
    std::vector<uint64_t> m_segmentElements;  // elements each segment holds (2^shift but the last)
    std::vector<Buffer> m_retired;            // replaced by a larger copy during reserve()
};

}  // namespace vkp::vk
