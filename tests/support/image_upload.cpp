#include "image_upload.h"

#include <cstring>

namespace pf::test {

Buffer createUploadBuffer(GpuResources& owner, const void* data, size_t size) {
    const Buffer upload = createHostBuffer(owner, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(upload.mapped, data, size);
    return upload;
}

void recordImageUpload(VkCommandBuffer cmd, const Buffer& upload, const Image& image, VkImageAspectFlags aspect,
                       VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, VkImageLayout layout) {
    imageBarrier(cmd, image.image, aspect,
                 {VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL});
    VkBufferImageCopy region{};
    region.imageSubresource = {aspect, 0, 0, 1};
    region.imageExtent = {image.extent.width, image.extent.height, 1};
    vkCmdCopyBufferToImage(cmd, upload.buffer, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    imageBarrier(cmd, image.image, aspect,
                 {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, dstStage, dstAccess,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layout});
}

} // namespace pf::test
