// Whether a count can fit at all: estimates of the GPU and host memory a
// field needs, compared with what the machine has. No Vulkan here, so the
// check is unit-tested with made-up limits (tests/tools/plantbench_memory_test.cpp).
#pragma once

#include "engine/field/sun_shadows.h"
#include "engine/scene/field_content.h"
#include "engine/scene/natural_density.h"
#include "engine/scene/plant_models.h"
#include "engine/vk/antialiasing.h"
#include "lsystem/common/memory_budget.h"

#include <cstdint>
#include <optional>
#include <string>

namespace pf {

// The biggest device-local heap (any heap when none is device-local): its
// size, or its budget when the device reports one.
struct HeapCapacity {
    uint64_t bytes = 0;
    bool fromBudget = false;
};

// Bytes a field of `count` plants needs on the GPU, about: per plant the
// instance (48 B), a visible-list entry per LOD (LOD_COUNT × 4 B), the LOD state
// (4 B) and the naive list entry (4 B); the model pool's vertices and
// indices when known; the render target (with its MSAA or FXAA image), its
// capture buffer and the shadow map; with ray-traced shadows also the
// field's graph (fieldGraphBytes, the models' triangles when known) and the
// frame's origins, depth and visibility (24 B a pixel).
uint64_t estimatedFieldBytes(uint64_t count, const PlantModelPool* pool, uint32_t width, uint32_t height,
                             const Antialiasing& antialiasing, SunShadows shadows = SunShadows::map);

// Host bytes building a field of `count` plants needs at its peak
// (kHostBytesPerPlant each, docs/PLANTBENCH.md): placement's grid and
// points, the placed, thinned and kept PlantInstance arrays, and the
// renderer's per-plant upload arrays; at natural densities also the heights
// of the grown terrain (kGrownTerrainBytesPerPlant at most).
inline constexpr uint64_t kHostBytesPerPlant = 160;
inline constexpr uint64_t kGrownTerrainBytesPerPlant = kGrownSamplesPerPlant * sizeof(float);
uint64_t estimatedHostBytes(uint64_t count, CountMode mode);

// Empty when `count` plants needing `bytes` of GPU memory fit `heap`, the
// largest heap of `device`; otherwise a message naming the count, the
// estimated need and the heap.
std::string gpuMemoryProblem(uint64_t count, uint64_t bytes, const std::string& device, const HeapCapacity& heap);
// Empty when `bytes` of host memory fit the memory budget (--memory-budget,
// lsystem/common/memory_budget.h); otherwise a message naming the count, the
// estimated need and the budget.
std::string hostMemoryProblem(uint64_t count, uint64_t bytes, const lsys::MemoryBudget& budget);

} // namespace pf
