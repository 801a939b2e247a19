#include "vk/segmented_buffer.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include <fmt/format.h>

#include "util/errors.h"
#include "util/host_memory.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp::vk {
namespace {

constexpr VkDeviceSize kSegmentBytes = VkDeviceSize(1) << 27;  // 128 MiB
constexpr VkDeviceSize kTableHeaderBytes = 16;                 // shift, mask, segments, pad (segmented.glsl)
constexpr uint64_t kMinGrowth = 4096;                          // elements a growing last segment adds at least

// The live tables and how many segments each addresses (segmentsAddressedBy), by handle: kernels
// bind a table as a plain storage buffer, so this is how a kernel learns what it bound.
std::mutex g_tablesMutex;
std::unordered_map<VkBuffer, size_t> g_tables;

void forgetTable(VkBuffer table) {
    if (table == VK_NULL_HANDLE) return;
    std::lock_guard lock(g_tablesMutex);
    g_tables.erase(table);
}

}  // namespace

std::optional<size_t> SegmentedBuffer::segmentsAddressedBy(VkBuffer table) {
    std::lock_guard lock(g_tablesMutex);
    const auto it = g_tables.find(table);
    if (it == g_tables.end()) return std::nullopt;
    return it->second;
}

SegmentedBuffer::~SegmentedBuffer() { forgetTable(m_table.handle()); }

SegmentedBuffer& SegmentedBuffer::operator=(SegmentedBuffer&& other) noexcept {
    if (this != &other) {
        forgetTable(m_table.handle());  // before the move releases it (its handle may be reused)
        m_context = std::exchange(other.m_context, nullptr);
        m_name = std::move(other.m_name);
        m_elementSize = other.m_elementSize;
        m_capacity = other.m_capacity;
        m_shift = other.m_shift;
        m_allocated = std::exchange(other.m_allocated, 0);
        m_table = std::move(other.m_table);
        m_segments = std::move(other.m_segments);
        m_segmentElements = std::move(other.m_segmentElements);
    }
    return *this;
}

uint32_t SegmentedBuffer::defaultSegmentShift(const Context& context, uint32_t elementSize) {
    const VkDeviceSize bytes = std::min(kSegmentBytes, context.maxAllocationSize());
    return static_cast<uint32_t>(std::bit_width(std::max<VkDeviceSize>(1, bytes / elementSize)) - 1);
}

SegmentedBuffer::SegmentedBuffer(Context& context, std::string name, uint32_t elementSize, uint64_t capacity,
                                 uint32_t segmentShift)
    : m_context(&context), m_name(std::move(name)), m_elementSize(elementSize), m_capacity(capacity),
      m_shift(segmentShift ? segmentShift : defaultSegmentShift(context, elementSize)) {
    if (m_shift >= 32) throw std::logic_error("SegmentedBuffer: segments of 2^32 elements or more");
    const uint64_t maxSegments = std::max<uint64_t>(1, (capacity + (uint64_t(1) << m_shift) - 1) >> m_shift);
    m_table = Buffer(context, m_name + " segment table", kTableHeaderBytes + maxSegments * sizeof(VkDeviceAddress),
                     kStorageUsage);
    writeTable();
}

uint64_t SegmentedBuffer::segmentElements(size_t segment) const {
    if (segment < m_segmentElements.size()) return m_segmentElements[segment];
    const uint64_t first = uint64_t(segment) << m_shift;
    return std::min<uint64_t>(uint64_t(1) << m_shift, m_capacity - first);
}

void SegmentedBuffer::reserve(uint64_t count) {
    count = std::min(count, m_capacity);
    if (count <= m_allocated) return;
    // A clear error before allocating what the device cannot hold. A CPU device (lavapipe)
    // allocates host memory and reports a nominal heap (2 GiB) it does not enforce: the limit is
    // the host's available memory, where the kernel's OOM killer would strike instead.
    const uint64_t needed = (count - m_allocated) * m_elementSize;
    const bool cpu = m_context->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const uint64_t limit = cpu ? hostMemoryAvailable() : m_context->deviceLocalHeapSize() - std::min(bytes(), m_context->deviceLocalHeapSize());
    if (needed > limit)
        throw RuntimeError(fmt::format("the {} needs {:.1f} MiB more for {} elements but the device '{}' has {:.1f} MiB "
                                       "{}: reduce the photon count",
                                       m_name, needed / 1048576.0, count, m_context->deviceName(), limit / 1048576.0,
                                       cpu ? "of host memory available" : "of memory left in its heap"));
    // Every segment but the last holds 2^shift elements; the last one holds what was reserved,
    // grown geometrically (x1.5, at least kMinGrowth elements) by a copy into a larger buffer:
    // an array allocates about what it holds, not a whole segment, and stays one segment
    // (the fast form of its kernels) until it passes 2^shift elements.
    m_context->submitAndWait([&](VkCommandBuffer cmd) {
        transferBarrier(cmd);  // earlier writes into the segment a copy reads
        while (m_allocated < count) {
            const size_t last = m_segments.size();
            const bool growLast = last > 0 && m_segmentElements.back() < (uint64_t(1) << m_shift);
            const size_t segment = growLast ? last - 1 : last;
            const uint64_t full = std::min<uint64_t>(uint64_t(1) << m_shift, m_capacity - (uint64_t(segment) << m_shift));
            const uint64_t held = growLast ? m_segmentElements.back() : 0;
            const uint64_t want = count - (uint64_t(segment) << m_shift);
            const uint64_t elements = std::min(full, std::max({want, held + held / 2, kMinGrowth}));
            Buffer buffer(*m_context, fmt::format("{} segment {}", m_name, segment),
                          std::max<VkDeviceSize>(16, elements * m_elementSize), kSegmentUsage);
            buffer.fillZero(cmd);
            if (growLast) {
                transferBarrier(cmd);  // the zeroing before the copy over it
                const VkBufferCopy region{0, 0, held * m_elementSize};
                vkCmdCopyBuffer(cmd, m_segments.back().handle(), buffer.handle(), 1, &region);
                m_retired.push_back(std::move(m_segments.back()));  // freed once the copy has run
                m_segments.back() = std::move(buffer);
                m_segmentElements.back() = elements;
            } else {
                m_segments.push_back(std::move(buffer));
                m_segmentElements.push_back(elements);
            }
            m_allocated += elements - held;
        }
        transferToComputeBarrier(cmd);
    });
    m_retired.clear();
    writeTable();
}

void SegmentedBuffer::writeTable() {
    std::vector<uint64_t> table(kTableHeaderBytes / sizeof(uint64_t) + m_segments.size());
    const uint32_t header[4] = {m_shift, (1u << m_shift) - 1u, static_cast<uint32_t>(m_segments.size()), 0u};
    std::memcpy(table.data(), header, sizeof(header));
    for (size_t i = 0; i < m_segments.size(); ++i) table[2 + i] = m_segments[i].deviceAddress();
    m_table.upload(table.data(), table.size() * sizeof(uint64_t));
    std::lock_guard lock(g_tablesMutex);
    g_tables[m_table.handle()] = m_segments.size();
}

uint64_t SegmentedBuffer::bytes() const {
    uint64_t total = 0;
    for (const Buffer& s : m_segments) total += s.size();
    return total;
}

void SegmentedBuffer::fillZero(VkCommandBuffer cmd) const {
    for (const Buffer& s : m_segments) s.fillZero(cmd);
}

void SegmentedBuffer::download(void* data, uint64_t first, uint64_t count) const {
    if (first + count > m_allocated) throw RuntimeError(fmt::format("download past the end of the {}", m_name));
    char* out = static_cast<char*>(data);
    forEachRun(first, count, [&](size_t segment, uint64_t offset, uint64_t n, uint64_t done) {
        m_segments[segment].download(out + done * m_elementSize, n * m_elementSize, offset * m_elementSize);
    });
}

void SegmentedBuffer::upload(const void* data, uint64_t first, uint64_t count) {
    reserve(first + count);
    if (first + count > m_allocated) throw RuntimeError(fmt::format("upload past the end of the {}", m_name));
    const char* in = static_cast<const char*>(data);
    forEachRun(first, count, [&](size_t segment, uint64_t offset, uint64_t n, uint64_t done) {
        m_segments[segment].upload(in + done * m_elementSize, n * m_elementSize, offset * m_elementSize);
    });
}

void SegmentedBuffer::recordCopyFrom(VkCommandBuffer cmd, const Buffer& src, std::span<const ElementCopy> copies) const {
    recordCopies(cmd, src, copies, true);
}

void SegmentedBuffer::recordCopyTo(VkCommandBuffer cmd, const Buffer& dst, std::span<const ElementCopy> copies) const {
    recordCopies(cmd, dst, copies, false);
}

void SegmentedBuffer::recordCopies(VkCommandBuffer cmd, const Buffer& buffer, std::span<const ElementCopy> copies,
                                   bool intoArray) const {
    std::vector<std::vector<VkBufferCopy>> regions(m_segments.size());
    for (const ElementCopy& copy : copies) {
        if (copy.first + copy.count > m_allocated) throw std::logic_error(fmt::format("copy past the end of the {}", m_name));
        if (copy.bufferOffset + copy.count * m_elementSize > buffer.size())
            throw std::logic_error(fmt::format("copy past the end of a buffer for the {}", m_name));
        forEachRun(copy.first, copy.count, [&](size_t segment, uint64_t offset, uint64_t n, uint64_t done) {
            const VkDeviceSize inBuffer = copy.bufferOffset + done * m_elementSize;
            const VkDeviceSize inSegment = offset * m_elementSize;
            regions[segment].push_back(intoArray ? VkBufferCopy{inBuffer, inSegment, n * m_elementSize}
                                                 : VkBufferCopy{inSegment, inBuffer, n * m_elementSize});
        });
    }
    for (size_t segment = 0; segment < regions.size(); ++segment) {
        if (regions[segment].empty()) continue;
        const VkBuffer array = m_segments[segment].handle();
        vkCmdCopyBuffer(cmd, intoArray ? buffer.handle() : array, intoArray ? array : buffer.handle(),
                        static_cast<uint32_t>(regions[segment].size()), regions[segment].data());
    }
}

}  // namespace vkp::vk
