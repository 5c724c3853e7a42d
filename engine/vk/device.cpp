#include "engine/vk/device.h"

#include "engine/vk/vk_check.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace pf {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* log = static_cast<ValidationLog*>(user);
    const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    std::string text =
        std::string(error ? "validation error: " : "validation warning: ") + (data->pMessage ? data->pMessage : "");
    {
        std::lock_guard lock(log->mutex);
        (error ? log->errorCount : log->warningCount)++;
        log->messages.push_back(text);
    }
    if (log->echoToStderr) std::fprintf(stderr, "%s\n", text.c_str());
    return VK_FALSE; // never abort the call: the application decides what a message means
}

bool layerAvailable(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
    }
}

// Hardware first; lavapipe (a CPU device) is the fallback.
int deviceTypeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
    }
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::vector<VkPhysicalDevice> enumeratePhysicalDevices(VkInstance instance) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    return devices;
}

// The first queue family with graphics and compute (and presentation to the
// surface, when there is one); UINT32_MAX when none.
uint32_t findQueueFamily(VkPhysicalDevice device, VkSurfaceKHR surface) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & needed) != needed) continue;
        if (surface) {
            VkBool32 present = VK_FALSE;
            vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &present);
            if (!present) continue;
        }
        return i;
    }
    return UINT32_MAX;
}

bool supportsRequiredFeatures(VkPhysicalDevice device) {
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13};
    vkGetPhysicalDeviceFeatures2(device, &features);
    return features13.dynamicRendering && features13.synchronization2;
}

} // namespace

uint32_t ValidationLog::count() const {
    std::lock_guard lock(mutex);
    return errorCount + warningCount;
}

std::vector<std::string> ValidationLog::snapshot() const {
    std::lock_guard lock(mutex);
    return messages;
}

void ValidationLog::clear() {
    std::lock_guard lock(mutex);
    messages.clear();
    errorCount = warningCount = 0;
}

bool validationWantedByDefault() {
    if (const char* env = std::getenv("PLANTFIELD_VALIDATION")) return std::strcmp(env, "0") != 0;
#ifdef NDEBUG
    return false;
#else
    return true;
#endif
}

void createInstance(GpuContext& ctx, const GpuOptions& options) {
    ctx.validationLog = std::make_unique<ValidationLog>();
    ctx.validationLog->echoToStderr = options.echoValidation;

    std::vector<const char*> extensions;
    for (const std::string& e : options.instanceExtensions) extensions.push_back(e.c_str());
    std::vector<const char*> layers;
    if (options.validation) {
        if (!layerAvailable(kValidationLayer))
            throw std::runtime_error(std::string("validation requested but ") + kValidationLayer +
                                     " is not installed (Debian package vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "plantfield";
    app.pEngineName = "plantfield";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
    messengerInfo.pfnUserCallback = onDebugMessage;
    messengerInfo.pUserData = ctx.validationLog.get();

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    // Chained so that instance creation and destruction are validated too.
    if (options.validation) info.pNext = &messengerInfo;
    VK_CHECK(vkCreateInstance(&info, nullptr, &ctx.instance));

    if (options.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx.instance, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(ctx.instance, &messengerInfo, nullptr, &ctx.messenger));
    }
}

std::vector<PhysicalDeviceInfo> listPhysicalDevices(VkInstance instance) {
    std::vector<PhysicalDeviceInfo> out;
    for (VkPhysicalDevice device : enumeratePhysicalDevices(instance)) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(device, &props);
        out.push_back({props.deviceName, deviceTypeName(props.deviceType), props.apiVersion});
    }
    return out;
}

void createDevice(GpuContext& ctx, const GpuOptions& options, VkSurfaceKHR surface) {
    std::string wanted = options.deviceName;
    if (wanted.empty())
        if (const char* env = std::getenv("PLANTFIELD_DEVICE")) wanted = env;
    wanted = lower(wanted);

    int bestRank = -1;
    std::string seen;
    for (VkPhysicalDevice device : enumeratePhysicalDevices(ctx.instance)) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(device, &props);
        seen += std::string(seen.empty() ? "" : ", ") + props.deviceName;
        if (!wanted.empty() && lower(props.deviceName).find(wanted) == std::string::npos) continue;
        if (props.apiVersion < VK_API_VERSION_1_3 || !supportsRequiredFeatures(device)) continue;
        uint32_t family = findQueueFamily(device, surface);
        if (family == UINT32_MAX) continue;
        int rank = deviceTypeRank(props.deviceType);
        if (rank > bestRank) {
            bestRank = rank;
            ctx.physicalDevice = device;
            ctx.queueFamily = family;
            ctx.properties = props;
        }
    }
    if (!ctx.physicalDevice)
        throw std::runtime_error(
            "no usable Vulkan 1.3 device" + (wanted.empty() ? std::string() : " matching '" + wanted + "'") +
            (surface ? " that can present to the window" : "") + " (found: " + (seen.empty() ? "none" : seen) + ")");
    vkGetPhysicalDeviceMemoryProperties(ctx.physicalDevice, &ctx.memoryProperties);
    ctx.hostMemoryLimit = options.hostMemoryLimit;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = ctx.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    // Optional features the field renderer uses when present: the count
    // variant of indirect draws, and shader-side draw parameters.
    VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported12};
    vkGetPhysicalDeviceFeatures2(ctx.physicalDevice, &supported);
    ctx.drawIndirectCount = supported12.drawIndirectCount == VK_TRUE;

    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features12.drawIndirectCount = supported12.drawIndirectCount;
    features12.hostQueryReset = supported12.hostQueryReset;
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &features12};
    features13.dynamicRendering = VK_TRUE;
    features13.synchronization2 = VK_TRUE;
    features13.maintenance4 = VK_TRUE; // compute shaders compiled for SPIR-V 1.6 declare LocalSizeId; core in 1.3
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13};
    // One indirect buffer holds many draws, each starting at its own instance.
    features.features.multiDrawIndirect = supported.features.multiDrawIndirect;
    features.features.drawIndirectFirstInstance = supported.features.drawIndirectFirstInstance;
    features.features.samplerAnisotropy = supported.features.samplerAnisotropy;
    ctx.multiDrawIndirect = supported.features.multiDrawIndirect == VK_TRUE;
    if (!supported.features.drawIndirectFirstInstance)
        throw std::runtime_error(std::string(ctx.properties.deviceName) + " lacks drawIndirectFirstInstance");

    std::vector<const char*> extensions;
    ctx.presentation = surface != VK_NULL_HANDLE;
    if (ctx.presentation) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateDevice(ctx.physicalDevice, &info, nullptr, &ctx.device));
    vkGetDeviceQueue(ctx.device, ctx.queueFamily, 0, &ctx.queue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily;
    VK_CHECK(vkCreateCommandPool(ctx.device, &poolInfo, nullptr, &ctx.commandPool));
}

void createHeadlessContext(GpuContext& ctx, const GpuOptions& options) {
    createInstance(ctx, options);
    createDevice(ctx, options);
}

void destroyContext(GpuContext& ctx) {
    if (ctx.device) {
        vkDeviceWaitIdle(ctx.device);
        if (ctx.commandPool) vkDestroyCommandPool(ctx.device, ctx.commandPool, nullptr);
        vkDestroyDevice(ctx.device, nullptr);
    }
    if (ctx.messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx.instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(ctx.instance, ctx.messenger, nullptr);
    }
    if (ctx.instance) vkDestroyInstance(ctx.instance, nullptr);
    ctx.device = VK_NULL_HANDLE;
    ctx.messenger = VK_NULL_HANDLE;
    ctx.instance = VK_NULL_HANDLE;
    ctx.commandPool = VK_NULL_HANDLE;
}

} // namespace pf
