// Turning VkResult failures into exceptions that say what was being attempted.
#pragma once
#include <string_view>

#include <vulkan/vulkan.h>

namespace vkp::vk {

const char* resultName(VkResult result);

// Throws vkp::RuntimeError("<what>: <VkResult name>"); device loss and out-of-memory get a hint.
[[noreturn]] void throwVkError(VkResult result, std::string_view what);

inline void check(VkResult result, std::string_view what) {
    if (result != VK_SUCCESS) throwVkError(result, what);
}

}  // namespace vkp::vk
