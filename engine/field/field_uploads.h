// What uploading a field to the GPU needs, checked before anything is
// uploaded: host memory for the staging copies, and buffers the device can
// bind.
#pragma once

#include "engine/scene/field_content.h"
#include "engine/vk/device.h"

#include <cstdint>

namespace pf {

// What uploading the field holds in host memory at once: the instance and
// naive lists built for the GPU and a staging copy of each, and the staging
// copies of the vertex and index pools (saturating). The GPU side is bounded
// by its heaps (GpuResources::allocate).
uint64_t fieldUploadBytes(const FieldContent& content);

// The vertex pool is bound whole as a storage buffer (the impostor bake) and
// read through uint4 texel views (the draw shaders); past either device limit
// those bindings are invalid, so a pool of more vertices is refused with its
// size (std::runtime_error).
void requireBindableVertexPool(const GpuContext& ctx, size_t vertices);

} // namespace pf
