#include "vk/context.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

#include "util/errors.h"
#include "shared/kernels/terminations.glsl"
#include "vk/buffer.h"
#include "vk/check.h"
#include "vk/compute_kernel.h"

namespace vkp::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
    }
}

// Lower is better: real GPUs first, lavapipe (CPU) last.
int deviceRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
    }
}

std::vector<VkPhysicalDevice> enumeratePhysicalDevices(VkInstance instance) {
    uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "enumerating physical devices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "enumerating physical devices");
    return devices;
}

// A queue family with compute (graphics too when available, for the raster pass).
bool findQueueFamily(VkPhysicalDevice device, uint32_t& family) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    int best = -1;
    for (uint32_t i = 0; i < count; ++i) {
        const VkQueueFlags flags = families[i].queueFlags;
        if (!(flags & VK_QUEUE_COMPUTE_BIT)) continue;
        if (best < 0 || (flags & VK_QUEUE_GRAPHICS_BIT)) best = static_cast<int>(i);
        if (flags & VK_QUEUE_GRAPHICS_BIT) break;
    }
    if (best < 0) return false;
    family = static_cast<uint32_t>(best);
    return true;
}

DeviceInfo describe(VkPhysicalDevice device, uint32_t index) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(device, &props);
    uint32_t family = 0;
    DeviceInfo info;
    info.index = index;
    info.name = props.deviceName;
    info.type = deviceTypeName(props.deviceType);
    info.apiVersion = props.apiVersion;
    info.suitable = props.apiVersion >= VK_API_VERSION_1_3 && findQueueFamily(device, family);
    return info;
}

// Whether the device offers VK_KHR_swapchain (a window's presentation needs it).
bool hasSwapchainExtension(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
    });
}

VkInstance createBareInstance(bool validate, const void* next, const std::vector<std::string>& requested = {}) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "vkphoton";
    app.applicationVersion = VK_MAKE_VERSION(0, 1, 0);
    app.pEngineName = "vkphoton";
    app.apiVersion = VK_API_VERSION_1_3;

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    for (const std::string& name : requested) extensions.push_back(name.c_str());
    if (validate) {
        uint32_t count = 0;
        vkEnumerateInstanceLayerProperties(&count, nullptr);
        std::vector<VkLayerProperties> available(count);
        vkEnumerateInstanceLayerProperties(&count, available.data());
        const bool found = std::any_of(available.begin(), available.end(), [](const auto& l) {
            return std::strcmp(l.layerName, kValidationLayer) == 0;
        });
        if (!found)
            throw RuntimeError(
                "validation requested but VK_LAYER_KHRONOS_validation is not installed "
                "(Debian: apt-get install vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        // Provided by the layer (when it is): lets a context turn on synchronization validation.
        uint32_t extensionCount = 0;
        vkEnumerateInstanceExtensionProperties(kValidationLayer, &extensionCount, nullptr);
        std::vector<VkExtensionProperties> layerExtensions(extensionCount);
        vkEnumerateInstanceExtensionProperties(kValidationLayer, &extensionCount, layerExtensions.data());
        for (const auto& e : layerExtensions)
            if (std::strcmp(e.extensionName, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME) == 0)
                extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = next;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    const VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw RuntimeError(
            "no Vulkan 1.3 driver found (Debian: apt-get install mesa-vulkan-drivers for lavapipe)");
    check(result, "creating the Vulkan instance");
    return instance;
}

}  // namespace

bool validationRequestedByEnvironment() {
    const char* value = std::getenv("VKPHOTON_VALIDATE");
    return value != nullptr && std::strcmp(value, "0") != 0 && *value != '\0';
}

std::vector<DeviceInfo> listDevices() {
    VkInstance instance = createBareInstance(false, nullptr);
    std::vector<DeviceInfo> result;
    try {
        const auto devices = enumeratePhysicalDevices(instance);
        for (uint32_t i = 0; i < devices.size(); ++i) result.push_back(describe(devices[i], i));
    } catch (...) {
        vkDestroyInstance(instance, nullptr);
        throw;
    }
    vkDestroyInstance(instance, nullptr);
    return result;
}

Context::Context(const ContextOptions& options)
    : m_validate(options.validate || validationRequestedByEnvironment()), m_canPresent(options.canPresent) {
    try {
        createInstance(options.synchronizationValidation, options.instanceExtensions);
        pickPhysicalDevice(options.device);
        createDevice();
        createTerminationCounters();
    } catch (...) {
        destroy();
        throw;
    }
}

Context::~Context() { destroy(); }

void Context::createTerminationCounters() {
    m_terminationCounters = std::make_unique<Buffer>(*this, "termination counters",
                                                     gpu::kTerminationCounterCount * sizeof(uint32_t), kStorageUsage);
    submitAndWait([&](VkCommandBuffer cmd) {
        m_terminationCounters->fillZero(cmd);
        transferToComputeBarrier(cmd);
    });
}

void Context::destroy() {
    if (m_device) {
        vkDeviceWaitIdle(m_device);
        m_pipelines.clear();
        m_terminationCounters.reset();
        if (m_fence) vkDestroyFence(m_device, m_fence, nullptr);
        if (m_commandPool) vkDestroyCommandPool(m_device, m_commandPool, nullptr);
        vkDestroyDevice(m_device, nullptr);
        m_device = VK_NULL_HANDLE;
    }
    if (m_messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(m_instance, m_messenger, nullptr);
        m_messenger = VK_NULL_HANDLE;
    }
    if (m_instance) {
        vkDestroyInstance(m_instance, nullptr);
        m_instance = VK_NULL_HANDLE;
    }
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onDebugMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    auto* self = static_cast<Context*>(user);
    const std::string text = data && data->pMessage ? data->pMessage : "(no message)";
    {
        std::lock_guard lock(self->m_messagesMutex);
        if (self->m_messages.size() < 64) self->m_messages.push_back(text);
    }
    ++self->m_messageCount;
    fmt::print(stderr, "validation: {}\n", text);
    return VK_FALSE;
}

void Context::createInstance(bool synchronizationValidation, const std::vector<std::string>& extensions) {
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &Context::onDebugMessage;
    messengerInfo.pUserData = this;
    // Synchronization validation (hazards between passes, e.g. the raster/compute hand-off).
    const VkValidationFeatureEnableEXT syncFeature = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &syncFeature;
    features.pNext = &messengerInfo;
    // Chaining the messenger info also reports problems during instance creation itself.
    const void* chain = synchronizationValidation ? static_cast<const void*>(&features) : &messengerInfo;
    m_instance = createBareInstance(m_validate, m_validate ? chain : nullptr, extensions);
    if (!m_validate) return;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(m_instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw RuntimeError("VK_EXT_debug_utils is not available");
    check(create(m_instance, &messengerInfo, nullptr, &m_messenger), "creating the debug messenger");
}

void Context::pickPhysicalDevice(const std::string& request) {
    const auto devices = enumeratePhysicalDevices(m_instance);
    if (devices.empty())
        throw RuntimeError("no Vulkan device found (Debian: apt-get install mesa-vulkan-drivers)");
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
    // A window: only devices that can present to it (headless commands never ask).
    if (m_canPresent)
        for (DeviceInfo& info : infos) {
            uint32_t family = 0;
            if (info.suitable && !(hasSwapchainExtension(devices[info.index]) && findQueueFamily(devices[info.index], family) &&
                                   m_canPresent(m_instance, devices[info.index], family)))
                info.suitable = false;
        }

    int chosen = -1;
    if (!request.empty()) {
        const bool numeric = std::all_of(request.begin(), request.end(), ::isdigit);
        for (const auto& info : infos) {
            const bool match = numeric ? std::to_string(info.index) == request
                                       : info.name.find(request) != std::string::npos;
            if (match) { chosen = static_cast<int>(info.index); break; }
        }
        if (chosen < 0) {
            std::string names;
            for (const auto& info : infos) names += fmt::format("\n  {}: {}", info.index, info.name);
            throw InputError(fmt::format("--device {}: no such device; available:{}", request, names));
        }
        if (!infos[chosen].suitable)
            throw InputError(fmt::format("--device {}: '{}' lacks Vulkan 1.3 or a compute queue{}",
                                         request, infos[chosen].name, m_canPresent ? ", or cannot present to the window" : ""));
    } else {
        for (const auto& info : infos) {
            if (!info.suitable) continue;
            VkPhysicalDeviceProperties a{}, b{};
            vkGetPhysicalDeviceProperties(devices[info.index], &a);
            if (chosen >= 0) vkGetPhysicalDeviceProperties(devices[chosen], &b);
            if (chosen < 0 || deviceRank(a.deviceType) < deviceRank(b.deviceType))
                chosen = static_cast<int>(info.index);
        }
        if (chosen < 0)
            throw RuntimeError(m_canPresent ? "no Vulkan 1.3 device with a compute queue that can present to the window found"
                                            : "no Vulkan 1.3 device with a compute queue found");
    }
    m_physicalDevice = devices[chosen];
    vkGetPhysicalDeviceProperties(m_physicalDevice, &m_properties);
    VkPhysicalDeviceMaintenance4Properties maintenance4{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_PROPERTIES};
    VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    maintenance3.pNext = &maintenance4;
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties2.pNext = &maintenance3;
    vkGetPhysicalDeviceProperties2(m_physicalDevice, &properties2);
    m_maxAllocationSize = std::min(maintenance3.maxMemoryAllocationSize, maintenance4.maxBufferSize);
    vkGetPhysicalDeviceMemoryProperties(m_physicalDevice, &m_memoryProperties);
    m_deviceName = m_properties.deviceName;
    findQueueFamily(m_physicalDevice, m_queueFamily);
}

void Context::createDevice() {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = m_queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    // maintenance4 (required of every Vulkan 1.3 device): glslang targeting Vulkan 1.3 emits
    // LocalSizeId for workgroup sizes.
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    features13.maintenance4 = VK_TRUE;
    // The raster pass (host/passes/shadow_volume_pass.h): dynamic rendering instead of render
    // pass objects, synchronization2 barriers; both core in 1.3 and required of every device.
    features13.dynamicRendering = VK_TRUE;
    features13.synchronization2 = VK_TRUE;
    // Photon maps larger than one storage buffer's range are segments reached through their
    // device addresses (vk/segmented_buffer.h); bufferDeviceAddress is required of every 1.3 device.
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features12.bufferDeviceAddress = VK_TRUE;
    features13.pNext = &features12;
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(m_physicalDevice, &supported);
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &features13;
    // Optional: the geometry-shader variant of the shadow volumes (measured against the compute
    // variant in docs/benchmarks.md).
    m_geometryShader = supported.geometryShader == VK_TRUE;
    features.features.geometryShader = supported.geometryShader;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    const char* swapchain = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    if (m_canPresent) {  // a window (host/view): the queue chosen above presents too
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &swapchain;
    }
    check(vkCreateDevice(m_physicalDevice, &info, nullptr, &m_device), "creating the logical device");
    vkGetDeviceQueue(m_device, m_queueFamily, 0, &m_queue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = m_queueFamily;
    check(vkCreateCommandPool(m_device, &poolInfo, nullptr, &m_commandPool), "creating a command pool");
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(m_device, &fenceInfo, nullptr, &m_fence), "creating a fence");
}

VkDeviceSize Context::deviceLocalHeapSize() const {
    VkDeviceSize largest = 0;
    for (uint32_t i = 0; i < m_memoryProperties.memoryHeapCount; ++i)
        if (m_memoryProperties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            largest = std::max(largest, m_memoryProperties.memoryHeaps[i].size);
    return largest;
}

std::vector<std::string> Context::validationMessages() const {
    std::lock_guard lock(m_messagesMutex);
    return m_messages;
}

void Context::throwOnValidationMessages() const {
    if (m_messageCount.load() == 0) return;
    const auto messages = validationMessages();
    throw RuntimeError(fmt::format("{} Vulkan validation message(s); first: {}", m_messageCount.load(),
                                   messages.empty() ? "" : messages.front()));
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                 VkMemoryPropertyFlags preferred) const {
    int fallback = -1;
    for (uint32_t i = 0; i < m_memoryProperties.memoryTypeCount; ++i) {
        if (!(typeBits & (1u << i))) continue;
        const VkMemoryPropertyFlags flags = m_memoryProperties.memoryTypes[i].propertyFlags;
        if ((flags & required) != required) continue;
        if ((flags & preferred) == preferred) return i;
        if (fallback < 0) fallback = static_cast<int>(i);
    }
    if (fallback < 0) throw RuntimeError("no suitable Vulkan memory type");
    return static_cast<uint32_t>(fallback);
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record,
                            double timeoutSeconds) {
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = m_commandPool;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(m_device, &allocInfo, &cmd), "allocating a command buffer");
    // Freed on every path except a hung submission, whose buffer may still be in use.
    struct Release {
        VkDevice device; VkCommandPool pool; VkCommandBuffer cmd; bool pending = false;
        ~Release() { if (!pending) vkFreeCommandBuffers(device, pool, 1, &cmd); }
    } release{m_device, m_commandPool, cmd};

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "beginning a command buffer");
    record(cmd);
    check(vkEndCommandBuffer(cmd), "ending a command buffer");

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(vkResetFences(m_device, 1, &m_fence), "resetting a fence");
    check(vkQueueSubmit(m_queue, 1, &submit, m_fence), "submitting work");
    const auto timeoutNs = static_cast<uint64_t>(timeoutSeconds * 1e9);
    const VkResult result = vkWaitForFences(m_device, 1, &m_fence, VK_TRUE, timeoutNs);
    release.pending = result == VK_TIMEOUT;
    if (result == VK_TIMEOUT)
        throw RuntimeError(fmt::format(
            "the device did not finish a submission within {:.0f} s; treating it as hung", timeoutSeconds));
    check(result, "waiting for the device");
    if (m_validate) throwOnValidationMessages();
}

}  // namespace vkp::vk
