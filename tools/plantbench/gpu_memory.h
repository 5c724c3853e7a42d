// How much GPU memory the sweep uses and how much the device has.
#pragma once

#include "memory_check.h"

#include "engine/vk/device.h"

#include <cstdint>

namespace pf {

// True when the physical device lists VK_EXT_memory_budget, whose heap
// budget and usage vkGetPhysicalDeviceMemoryProperties2 then reports.
bool hasMemoryBudget(const GpuContext& ctx);

// Bytes in use on the device-local heaps (VK_EXT_memory_budget's heapUsage).
uint64_t deviceLocalUsage(const GpuContext& ctx);

// The biggest device-local heap (any heap when none is device-local): its
// size, or its budget when the device reports one.
HeapCapacity largestDeviceLocalHeap(const GpuContext& ctx, bool budget);

} // namespace pf
