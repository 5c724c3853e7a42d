#include "engine/field/field_uploads.h"

#include "lsystem/common/memory_budget.h"
#include "shaders/shared/field_layouts.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pf {

uint64_t fieldUploadBytes(const FieldContent& content) {
    constexpr uint64_t kPerPlant = 2 * (sizeof(gpu::FieldInstance) + sizeof(uint32_t));
    uint64_t bytes = lsys::bytesTimes(content.plants.size(), kPerPlant);
    bytes = lsys::bytesPlus(bytes, lsys::bytesTimes(content.models.vertices.size(), sizeof(gpu::FieldVertex)));
    return lsys::bytesPlus(bytes, lsys::bytesTimes(content.models.indices.size(), sizeof(uint32_t)));
}

void requireBindableVertexPool(const GpuContext& ctx, size_t vertices) {
    const VkPhysicalDeviceLimits& limits = ctx.properties.limits;
    const uint64_t bytes = uint64_t(vertices) * sizeof(gpu::FieldVertex);
    const uint64_t texels = bytes / (4 * sizeof(uint32_t));
    if (bytes <= limits.maxStorageBufferRange && texels <= limits.maxTexelBufferElements) return;
    const auto mib = [](uint64_t b) { return std::to_string((b + (1 << 20) - 1) >> 20) + " MiB"; };
    throw DeviceLimitError(
        "the plant models' vertex pool (" + std::to_string(vertices) + " vertices, " + mib(bytes) +
        ") is larger than this device binds as one buffer (" +
        mib(std::min<uint64_t>(limits.maxStorageBufferRange, uint64_t(limits.maxTexelBufferElements) * 16)) +
        ", maxStorageBufferRange and maxTexelBufferElements): use fewer variants, fewer "
        "derivation steps or simpler plants");
}

} // namespace pf
