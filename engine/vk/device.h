// Vulkan instance, debug messenger, physical device choice and the logical
// device with its one graphics+compute queue.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace pf {

// Collects what the Khronos validation layer reports. Tests fail on any
// message; tools print them as they come.
struct ValidationLog {
    mutable std::mutex mutex;
    std::vector<std::string> messages; // warnings and errors, in order
    uint32_t errorCount = 0;
    uint32_t warningCount = 0;
    bool echoToStderr = true;

    uint32_t count() const;
    std::vector<std::string> snapshot() const;
    void clear();
};

struct GpuOptions {
    bool validation = false;
    // Case-insensitive substring of the device name; when empty the
    // PLANTFIELD_DEVICE environment variable is used, then the best device.
    std::string deviceName;
    std::vector<std::string> instanceExtensions; // e.g. what GLFW needs
    bool echoValidation = true;
    // On a device that is the CPU (lavapipe), device memory is host memory:
    // all of it held at once is counted against this (the tools' memory
    // budget, lsystem/common/memory_budget.h), so a frame too large for the
    // machine is refused by name instead of ending in the kernel's OOM killer.
    uint64_t hostMemoryLimit = UINT64_MAX;
};

// Work the device cannot take — an image past its largest side, an
// allocation past its heap, a buffer past its binding range, more plants than
// a pass draws: the size of the input, not a fault of the program, so the
// tools report it as they report bad input (exit 2).
struct DeviceLimitError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct GpuContext {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    bool presentation = false;      // VK_KHR_swapchain enabled
    bool drawIndirectCount = false; // vkCmdDrawIndexedIndirectCount usable
    bool multiDrawIndirect = false; // indirect draws with drawCount > 1
    std::unique_ptr<ValidationLog> validationLog;
    // GpuOptions::hostMemoryLimit, and the device memory held now (counted by
    // GpuResources on a CPU device).
    uint64_t hostMemoryLimit = UINT64_MAX;
    std::shared_ptr<std::atomic<uint64_t>> hostMemoryHeld = std::make_shared<std::atomic<uint64_t>>(0);
};

// Step 1: the instance (and the messenger when validation is on).
void createInstance(GpuContext& ctx, const GpuOptions& options);
// Step 2: pick a physical device and create the logical device. With a
// surface, only devices whose queue can present to it are considered and
// VK_KHR_swapchain is enabled.
void createDevice(GpuContext& ctx, const GpuOptions& options, VkSurfaceKHR surface = VK_NULL_HANDLE);
// Both steps for headless use.
void createHeadlessContext(GpuContext& ctx, const GpuOptions& options);
void destroyContext(GpuContext& ctx);

struct PhysicalDeviceInfo {
    std::string name;
    std::string type; // "discrete", "integrated", "virtual", "cpu", "other"
    uint32_t apiVersion = 0;
};
std::vector<PhysicalDeviceInfo> listPhysicalDevices(VkInstance instance);

// Validation defaults to on in debug builds and when PLANTFIELD_VALIDATION=1.
bool validationWantedByDefault();

} // namespace pf
