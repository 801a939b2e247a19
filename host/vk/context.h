// The Vulkan instance, the chosen physical device, one compute+graphics queue and a command pool.
// Device choice: discrete GPU, then integrated, then anything else (lavapipe); `--device` overrides.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/compute_pipeline.h"
#include "vk/memory_tracker.h"

namespace vkp::vk {

class Buffer;

struct ContextOptions {
    bool validate = false;      // enable VK_LAYER_KHRONOS_validation; every message is an error
    std::string device;         // "" = automatic; a decimal index or a substring of the name
    bool synchronizationValidation = false;  // with validate: also the layer's hazard tracking
    // Presentation (`vkphoton view`): the instance extensions the window system needs (GLFW's
    // list), and `canPresent`, which says whether a device's queue family can present to it.
    // With canPresent set only devices that can (and have VK_KHR_swapchain) are chosen and the
    // device enables VK_KHR_swapchain. Left empty (every other command): no surface extension is
    // asked for, so rendering needs no display.
    std::vector<std::string> instanceExtensions;
    std::function<bool(VkInstance, VkPhysicalDevice, uint32_t queueFamily)> canPresent;
};

struct DeviceInfo {
    uint32_t index = 0;
    std::string name;
    std::string type;           // "discrete", "integrated", "cpu", ...
    uint32_t apiVersion = 0;
    bool suitable = false;      // Vulkan 1.3 with a compute queue
};

// Lists the physical devices (a throwaway instance without layers).
std::vector<DeviceInfo> listDevices();

class Context {
public:
    explicit Context(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return m_instance; }
    // The silent-termination counters every kernel that declares them shares (set
    // gpu::kTerminationSet; shaders/shared/kernels/terminations.glsl), created zero with the device.
    const Buffer& terminationCounters() const { return *m_terminationCounters; }
    // The compiled pipeline for a kernel interface: made on first use, then shared for the
    // context's lifetime (compiling is the slow part of creating a kernel on lavapipe).
    // Shaders that trace rays get one per scene specialization (SceneSpecialization), shaders that
    // bind segmented arrays one for arrays of one segment and one for any (singleSegment).
    const ComputePipeline& computePipeline(const KernelInterface& interface, SceneSpecialization scene = {},
                                           bool singleSegment = false) const {
        return m_pipelines.get(*this, interface, scene, singleSegment);
    }
    // How many distinct compute pipelines this context has compiled.
    size_t computePipelineCount() const { return m_pipelines.size(); }

    VkPhysicalDevice physicalDevice() const { return m_physicalDevice; }
    VkDevice device() const { return m_device; }
    VkQueue queue() const { return m_queue; }
    uint32_t queueFamily() const { return m_queueFamily; }
    const VkPhysicalDeviceProperties& properties() const { return m_properties; }
    const std::string& deviceName() const { return m_deviceName; }
    bool validationEnabled() const { return m_validate; }
    // Whether VK_KHR_swapchain is enabled (ContextOptions::canPresent was set).
    bool presentationEnabled() const { return static_cast<bool>(m_canPresent); }
    bool geometryShaderEnabled() const { return m_geometryShader; }
    // Largest single buffer: maxMemoryAllocationSize and maxBufferSize, the smaller.
    VkDeviceSize maxAllocationSize() const { return m_maxAllocationSize; }
    // Device memory held by this context's buffers and images, now and at most (vk/memory_tracker.h).
    MemoryTracker& memory() const { return m_memory; }
    // Size of the largest device-local memory heap (what buffers of the device can hold at most).
    VkDeviceSize deviceLocalHeapSize() const;

    // Validation messages (warnings and errors) seen so far; tests assert this stays empty.
    std::vector<std::string> validationMessages() const;
    size_t validationMessageCount() const { return m_messageCount.load(); }
    // Throws RuntimeError listing the messages if any arrived (used after each submit with --validate).
    void throwOnValidationMessages() const;

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred) const;

    // Records commands with `record`, submits them and waits on a fence with a timeout: a device
    // that does not finish in `timeoutSeconds` is reported as hung instead of hanging the run.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record,
                       double timeoutSeconds = 600.0);

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(
        VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

    void destroy();
    void createInstance(bool synchronizationValidation, const std::vector<std::string>& extensions);
    void pickPhysicalDevice(const std::string& request);
    void createDevice();
    void createTerminationCounters();

    bool m_validate = false;
    std::function<bool(VkInstance, VkPhysicalDevice, uint32_t)> m_canPresent;
    bool m_geometryShader = false;
    VkInstance m_instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
    VkPhysicalDevice m_physicalDevice = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties m_properties{};
    VkPhysicalDeviceMemoryProperties m_memoryProperties{};
    VkDeviceSize m_maxAllocationSize = 0;
    mutable MemoryTracker m_memory;
    std::string m_deviceName;
    uint32_t m_queueFamily = 0;
    VkDevice m_device = VK_NULL_HANDLE;
    VkQueue m_queue = VK_NULL_HANDLE;
    VkCommandPool m_commandPool = VK_NULL_HANDLE;
    VkFence m_fence = VK_NULL_HANDLE;
    std::unique_ptr<Buffer> m_terminationCounters;
    mutable ComputePipelineCache m_pipelines;

    mutable std::atomic<size_t> m_messageCount{0};
    mutable std::mutex m_messagesMutex;
    std::vector<std::string> m_messages;  // guarded by m_messagesMutex
};

// True when VKPHOTON_VALIDATE=1 is set (the test suite sets it for every test).
bool validationRequestedByEnvironment();

}  // namespace vkp::vk
