// Synthetic input for a pass under test: bytes copied into level 0 of an
// image, which then stands as the pass expects to find it.
#pragma once

#include "engine/vk/resources.h"

#include <cstddef>

namespace pf::test {

// A host buffer holding `size` bytes of `data`, for recordImageUpload.
Buffer createUploadBuffer(GpuResources& owner, const void* data, size_t size);

// Records the copy of `upload` into level 0 of `image` (from an undefined
// layout) and the transition to its reader: `dstStage`, `dstAccess`, `layout`.
void recordImageUpload(VkCommandBuffer cmd, const Buffer& upload, const Image& image, VkImageAspectFlags aspect,
                       VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, VkImageLayout layout);

} // namespace pf::test
