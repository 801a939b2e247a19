// Segmented arrays (vk/segmented_buffer.h) allocate about what they are asked to hold: the last
// segment grows by copies that keep its elements, whole segments follow past 2^shift elements;
// the context counts the device memory its buffers hold and the most they held at once.
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/segmented_buffer.h"

namespace vkp {
namespace {

class SegmentedBufferTest : public test::GpuTest {};

TEST_F(SegmentedBufferTest, GrowsWithWhatItHoldsAndKeepsItsElements) {
    vk::Context& context = test::gpu();
    constexpr uint32_t kShift = 14;  // 16384 elements per segment
    vk::SegmentedBuffer array(context, "test array", sizeof(uint32_t), 100000, kShift);
    EXPECT_EQ(array.bytes(), 0u);
    std::vector<uint32_t> values(60000);
    std::iota(values.begin(), values.end(), 7u);
    uint64_t written = 0;
    for (const uint64_t count : {100u, 5000u, 9000u, 16384u, 20000u, 60000u}) {
        array.reserve(count);
        EXPECT_GE(array.allocated(), count);
        // About what was asked: whole segments below, the last one within x1.5 or 4096 elements.
        const uint64_t lastStart = (count - 1) >> kShift << kShift;
        EXPECT_LE(array.allocated(), lastStart + std::max<uint64_t>(4096, (count - lastStart) * 3 / 2)) << count;
        EXPECT_EQ(array.bytes(), array.allocated() * sizeof(uint32_t)) << count;
        EXPECT_EQ(array.segmentCount(), ((count - 1) >> kShift) + 1) << count;
        // What was written before the growth is still there; the new room reads zero.
        const std::vector<uint32_t> back = array.download<uint32_t>(array.allocated());
        for (uint64_t i = 0; i < written; ++i) ASSERT_EQ(back[i], values[i]) << "element " << i << " after growing to " << count;
        for (uint64_t i = written; i < back.size(); ++i) ASSERT_EQ(back[i], 0u) << "element " << i;
        array.upload(values.data() + written, written, count - written);
        written = count;
    }
}

TEST_F(SegmentedBufferTest, TheContextCountsHeldDeviceMemoryAndItsPeak) {
    vk::Context& context = test::gpu();
    vk::MemoryTracker& memory = context.memory();
    memory.resetPeak();
    const uint64_t before = memory.current();
    EXPECT_EQ(memory.peak(), before);
    {
        const vk::Buffer a(context, "counted a", 1u << 20, vk::kStorageUsage);
        EXPECT_GE(memory.current(), before + (1u << 20));
        {
            const vk::Buffer b(context, "counted b", 3u << 20, vk::kStorageUsage);
            EXPECT_GE(memory.current(), before + (4u << 20));
        }
        EXPECT_LT(memory.current(), before + (4u << 20));
    }
    EXPECT_EQ(memory.current(), before);
    EXPECT_GE(memory.peak(), before + (4u << 20));
    EXPECT_LT(memory.peak(), before + (5u << 20));
}

}  // namespace
}  // namespace vkp
