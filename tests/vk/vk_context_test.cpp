// The Vulkan layer: device choice, buffer limits, validation plumbing.
#include <gtest/gtest.h>

#include "support/gpu_test_support.h"
#include "util/errors.h"
#include "vk/buffer.h"
#include "vk/shader_registry.h"

namespace vkp {
namespace {

class VkContext : public test::GpuTest {};

TEST_F(VkContext, LavapipeIsChosenWithValidation) {
    vk::Context& context = test::gpu();
    EXPECT_TRUE(context.validationEnabled());
    EXPECT_GE(context.properties().apiVersion, VK_API_VERSION_1_3);
    EXPECT_FALSE(context.deviceName().empty());
}

TEST_F(VkContext, StorageBuffersBeyondTheDeviceRangeAreRefusedByName) {
    vk::Context& context = test::gpu();
    const VkDeviceSize limit = context.properties().limits.maxStorageBufferRange;
    try {
        vk::Buffer huge(context, "photon map", limit + 16, vk::kStorageUsage);
        FAIL() << "a buffer above maxStorageBufferRange was created";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("photon map"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("MiB"), std::string::npos) << e.what();
    }
}

TEST_F(VkContext, BufferRoundTrip) {
    vk::Context& context = test::gpu();
    std::vector<uint32_t> data(1000);
    for (uint32_t i = 0; i < data.size(); ++i) data[i] = i * 2654435761u;
    vk::Buffer buffer = vk::makeStorageBuffer(context, "round trip", data);
    EXPECT_EQ(buffer.download<uint32_t>(), data);
}

TEST_F(VkContext, UnknownShaderIsARuntimeError) {
    EXPECT_THROW(vk::shaderCode("no-such-shader.comp"), RuntimeError);
}

TEST(VkDevices, ListIncludesASuitableDevice) {
    const auto devices = vk::listDevices();
    ASSERT_FALSE(devices.empty());
    bool suitable = false;
    for (const auto& d : devices) suitable = suitable || d.suitable;
    EXPECT_TRUE(suitable);
}

TEST(VkDevices, UnknownDeviceRequestIsAnInputError) {
    vk::ContextOptions options;
    options.device = "no-such-device-name";
    EXPECT_THROW(vk::Context context(options), InputError);
}

}  // namespace
}  // namespace vkp
