#include "device_memory.h"

#include <mutex>
#include <unordered_map>

namespace pf::test {
namespace {

struct DeviceMemoryCount {
    std::mutex mutex;
    std::unordered_map<VkDeviceMemory, VkDeviceSize> live;
    VkDeviceSize bytes = 0;
};

DeviceMemoryCount& count() {
    static DeviceMemoryCount c;
    return c;
}

} // namespace

VkDeviceSize liveDeviceMemoryBytes() {
    std::lock_guard lock(count().mutex);
    return count().bytes;
}

} // namespace pf::test

// The definitions that replace the loader's exports for this executable:
// calls from the engine bind to them at link time, and they forward to the
// device's own entry points (the validation layer first), looked up each
// time because every test makes its own device.
extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkAllocateMemory(VkDevice device, const VkMemoryAllocateInfo* info,
                                                           const VkAllocationCallbacks* allocator,
                                                           VkDeviceMemory* memory) {
    const auto next = reinterpret_cast<PFN_vkAllocateMemory>(vkGetDeviceProcAddr(device, "vkAllocateMemory"));
    const VkResult result = next(device, info, allocator, memory);
    if (result == VK_SUCCESS) {
        pf::test::DeviceMemoryCount& c = pf::test::count();
        std::lock_guard lock(c.mutex);
        c.live[*memory] = info->allocationSize;
        c.bytes += info->allocationSize;
    }
    return result;
}

extern "C" VKAPI_ATTR void VKAPI_CALL vkFreeMemory(VkDevice device, VkDeviceMemory memory,
                                                   const VkAllocationCallbacks* allocator) {
    const auto next = reinterpret_cast<PFN_vkFreeMemory>(vkGetDeviceProcAddr(device, "vkFreeMemory"));
    next(device, memory, allocator);
    pf::test::DeviceMemoryCount& c = pf::test::count();
    std::lock_guard lock(c.mutex);
    if (const auto it = c.live.find(memory); it != c.live.end()) {
        c.bytes -= it->second;
        c.live.erase(it);
    }
}
