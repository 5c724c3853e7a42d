#include "memory_check.h"

#include "engine/raytrace/field_graph.h"
#include "shaders/shared/field_layouts.h"

namespace pf {

uint64_t estimatedFieldBytes(uint64_t count, const PlantModelPool* pool, uint32_t width, uint32_t height,
                             const Antialiasing& antialiasing, SunShadows shadows) {
    // An instance, its visible entries in the camera's lists and in both
    // shadow-caster passes' lists, its LOD state and its naive entry.
    constexpr uint64_t kPerPlant = sizeof(gpu::FieldInstance) + 3 * LOD_COUNT * 4 + 4 + 4;
    constexpr uint64_t kShadowMap = 2048ull * 2048 * 4; // the frame's map and the cache of static casters
    const uint64_t pixels = uint64_t(width) * height;
    const uint64_t samples = colorPassSamples(antialiasing);
    // The finished colour image and the depth, plus the image the colour pass
    // draws into when it is another (MSAA or FXAA), 4 bytes a sample each.
    const bool drawnApart = samples > 1 || antialiasing.method == AntialiasMethod::fxaa;
    const uint64_t target = pixels * 4 + pixels * samples * 4 * (drawnApart ? 2 : 1);
    const uint64_t capture = pixels * 4;
    // The depth pyramid: level 0 (a power of two a side, no larger than the
    // target) and its mips, 4 bytes a texel, at most 4/3 of a pixel each.
    const uint64_t pyramid = pixels * 4 * 4 / 3;
    uint64_t bytes = count * kPerPlant + target + capture + pyramid + kShadowMap;
    if (pool) bytes += pool->vertices.size() * sizeof(gpu::FieldVertex) + pool->indices.size() * 4;
    if (shadows == SunShadows::raytraced)
        bytes += fieldGraphBytes(pool ? *pool : PlantModelPool{}, count) + pixels * (16 + 4 + 4);
    return bytes;
}

uint64_t estimatedHostBytes(uint64_t count, CountMode mode) {
    return count * (kHostBytesPerPlant + (mode == CountMode::NaturalDensity ? kGrownTerrainBytesPerPlant : 0));
}

std::string gpuMemoryProblem(uint64_t count, uint64_t bytes, const std::string& device, const HeapCapacity& heap) {
    if (bytes <= heap.bytes) return {};
    return std::to_string(count) + " plants need about " + lsys::formatBytes(bytes) +
           " of GPU memory, but the largest device-local heap of " + device +
           (heap.fromBudget ? " has a budget of " : " holds ") + lsys::formatBytes(heap.bytes) +
           ": measure fewer plants";
}

std::string hostMemoryProblem(uint64_t count, uint64_t bytes, const lsys::MemoryBudget& budget) {
    if (bytes <= budget.limitBytes) return {};
    return std::to_string(count) + " plants need about " + lsys::formatBytes(bytes) +
           " of host memory to build the field, but the memory budget is " + lsys::formatBytes(budget.limitBytes) +
           " (--memory-budget; by default 3/4 of the memory this process may use): measure fewer plants";
}

} // namespace pf
