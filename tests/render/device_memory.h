// The device memory this test process holds, counted independently of the
// engine: device_memory.cpp defines vkAllocateMemory and vkFreeMemory for the
// executable it is linked into, so every allocation the engine's static
// libraries make passes through the count before reaching the driver.
#pragma once

#include <vulkan/vulkan.h>

namespace pf::test {

// Bytes of every allocation made and not yet freed.
VkDeviceSize liveDeviceMemoryBytes();

} // namespace pf::test
