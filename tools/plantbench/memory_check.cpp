#include "memory_check.h"

#include "shaders/field_layouts.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace pf {

uint64_t estimatedFieldBytes(uint64_t count, const PlantModelPool* pool, uint32_t width, uint32_t height,
                             const Antialiasing& antialiasing) {
    // An instance, its visible entries in the camera's lists and in both
    // shadow-caster passes' lists, its LOD state and its naive entry.
    constexpr uint64_t kPerPlant = sizeof(gpu::FieldInstance) + 3 * LOD_COUNT * 4 + 4 + 4;
    constexpr uint64_t kShadowMap = 2048ull * 2048 * 4; // the frame's map and the cache of static casters
    const uint64_t pixels = uint64_t(width) * height;
    const uint64_t samples = colourPassSamples(antialiasing);
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
    return bytes;
}

uint64_t estimatedHostBytes(uint64_t count, CountMode mode) {
    return count * (kHostBytesPerPlant + (mode == CountMode::NaturalDensity ? kGrownTerrainBytesPerPlant : 0));
}

std::optional<uint64_t> memAvailableOf(const std::string& meminfo) {
    std::istringstream lines(meminfo);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream fields(line);
        std::string key, unit;
        uint64_t value = 0;
        if (!(fields >> key >> value) || key != "MemAvailable:") continue;
        fields >> unit;
        return unit == "kB" ? value * 1024 : value;
    }
    return std::nullopt;
}

std::optional<uint64_t> hostMemoryAvailable() {
    std::ifstream in("/proc/meminfo");
    if (!in) return std::nullopt;
    return memAvailableOf(std::string(std::istreambuf_iterator<char>(in), {}));
}

std::string gpuMemoryProblem(uint64_t count, uint64_t bytes, const std::string& device, const HeapCapacity& heap) {
    if (bytes <= heap.bytes) return {};
    return std::to_string(count) + " plants need about " + formatBytes(bytes) +
           " of GPU memory, but the largest device-local heap of " + device +
           (heap.fromBudget ? " has a budget of " : " holds ") + formatBytes(heap.bytes) + ": measure fewer plants";
}

std::string hostMemoryProblem(uint64_t count, uint64_t bytes, std::optional<uint64_t> available) {
    if (!available || bytes <= *available) return {};
    return std::to_string(count) + " plants need about " + formatBytes(bytes) +
           " of host memory to build the field, but only " + formatBytes(*available) +
           " is available (MemAvailable in /proc/meminfo): measure fewer plants";
}

std::string formatBytes(uint64_t bytes) {
    char text[32];
    if (bytes >= (1ull << 30))
        std::snprintf(text, sizeof(text), "%.1f GiB", double(bytes) / double(1ull << 30));
    else if (bytes >= (1ull << 20))
        std::snprintf(text, sizeof(text), "%.1f MiB", double(bytes) / double(1ull << 20));
    else
        std::snprintf(text, sizeof(text), "%llu B", static_cast<unsigned long long>(bytes));
    return text;
}

} // namespace pf
