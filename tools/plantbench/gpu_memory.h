// How much GPU memory the sweep uses and whether a count can fit at all.
#pragma once

#include "engine/device.h"
#include "engine/plant_models.h"

#include <cstdint>
#include <string>

namespace pf {

// True when the physical device lists VK_EXT_memory_budget, whose heap
// budget and usage vkGetPhysicalDeviceMemoryProperties2 then reports.
bool hasMemoryBudget(const GpuContext& ctx);

// Bytes in use on the device-local heaps (VK_EXT_memory_budget's heapUsage).
uint64_t deviceLocalUsage(const GpuContext& ctx);

// The biggest device-local heap (any heap when none is device-local): its
// size, or its budget when the device reports one.
struct HeapCapacity {
    uint64_t bytes = 0;
    bool fromBudget = false;
};
HeapCapacity largestDeviceLocalHeap(const GpuContext& ctx, bool budget);

// Bytes a field of `count` plants needs on the GPU, about: per plant the
// instance (48 B), a visible-list entry per LOD (3 × 4 B), the LOD state
// (4 B) and the naive list entry (4 B); the model pool's vertices and
// indices when known; the render target and the shadow map.
uint64_t estimatedFieldBytes(uint64_t count, const PlantModelPool* pool, uint32_t width, uint32_t height,
                             uint32_t samples);

// "1.5 GiB", "12.0 MiB", "800 B".
std::string formatBytes(uint64_t bytes);

} // namespace pf
