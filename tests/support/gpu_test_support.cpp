#include "support/gpu_test_support.h"

#include "vk/buffer.h"
#include "vk/shader_registry.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace vkp::embedded {
extern const vk::ShaderEntry* const vkphoton_test_shaders_table[];
}

namespace vkp::test {
namespace {
size_t g_seenMessages = 0;
}

void registerTestShaders() {
    static const bool registered = [] {
        vk::registerShaderTable(embedded::vkphoton_test_shaders_table);
        return true;
    }();
    (void)registered;
}

vk::Context& gpu() {
    static std::unique_ptr<vk::Context> context = [] {
        registerTestShaders();
        vk::ContextOptions options;
        options.validate = true;
        return std::make_unique<vk::Context>(options);
    }();
    return *context;
}

bool onLavapipe() { return gpu().deviceName().find("llvmpipe") != std::string::npos; }

uint32_t ulpDistance(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<uint32_t>::max();
    // Floats of one sign are ordered like their bit patterns; map both signs onto one line.
    const auto line = [](float f) {
        const int64_t bits = std::bit_cast<int32_t>(f);
        return bits < 0 ? -(bits & 0x7fffffff) : bits;
    };
    const int64_t d = line(a) - line(b);
    return static_cast<uint32_t>(std::min<int64_t>(d < 0 ? -d : d, std::numeric_limits<uint32_t>::max()));
}

void poisonDeviceMemory(uint64_t bytes) {
    vk::Context& context = gpu();
    for (uint64_t left = bytes; left > 0;) {
        const uint64_t chunk = std::min<uint64_t>(left, 64u << 20);
        vk::Buffer buffer(context, "poison", chunk, vk::kStorageUsage);
        context.submitAndWait([&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, 0x3c013c01u); });
        left -= chunk;
    }
}

void expectNoValidationMessages() {
    vk::Context& context = gpu();
    const size_t count = context.validationMessageCount();
    if (count != g_seenMessages) {
        const auto messages = context.validationMessages();
        ADD_FAILURE() << (count - g_seenMessages) << " validation message(s); first recorded: "
                      << (messages.empty() ? "" : messages.front());
        g_seenMessages = count;
    }
}

}  // namespace vkp::test
