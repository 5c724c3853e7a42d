#include "gpu_memory.h"

#include <cstring>
#include <vector>

namespace pf {

bool hasMemoryBudget(const GpuContext& ctx) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(ctx.physicalDevice, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> extensions(n);
    vkEnumerateDeviceExtensionProperties(ctx.physicalDevice, nullptr, &n, extensions.data());
    for (const VkExtensionProperties& e : extensions)
        if (std::strcmp(e.extensionName, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME) == 0) return true;
    return false;
}

namespace {

VkPhysicalDeviceMemoryBudgetPropertiesEXT queryBudget(const GpuContext& ctx) {
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
    VkPhysicalDeviceMemoryProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2};
    properties.pNext = &budget;
    vkGetPhysicalDeviceMemoryProperties2(ctx.physicalDevice, &properties);
    return budget;
}

bool deviceLocal(const VkMemoryHeap& heap) { return (heap.flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) != 0; }

} // namespace

uint64_t deviceLocalUsage(const GpuContext& ctx) {
    const VkPhysicalDeviceMemoryBudgetPropertiesEXT budget = queryBudget(ctx);
    uint64_t bytes = 0;
    for (uint32_t h = 0; h < ctx.memoryProperties.memoryHeapCount; ++h)
        if (deviceLocal(ctx.memoryProperties.memoryHeaps[h])) bytes += budget.heapUsage[h];
    return bytes;
}

HeapCapacity largestDeviceLocalHeap(const GpuContext& ctx, bool budget) {
    const VkPhysicalDeviceMemoryProperties& memory = ctx.memoryProperties;
    bool anyDeviceLocal = false;
    for (uint32_t h = 0; h < memory.memoryHeapCount; ++h) anyDeviceLocal |= deviceLocal(memory.memoryHeaps[h]);
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budgets{};
    if (budget) budgets = queryBudget(ctx);
    HeapCapacity largest;
    for (uint32_t h = 0; h < memory.memoryHeapCount; ++h) {
        if (anyDeviceLocal && !deviceLocal(memory.memoryHeaps[h])) continue;
        const bool reported = budget && budgets.heapBudget[h] > 0;
        const uint64_t bytes = reported ? budgets.heapBudget[h] : memory.memoryHeaps[h].size;
        if (bytes > largest.bytes) largest = {bytes, reported};
    }
    return largest;
}

} // namespace pf
