#include "engine/vk/capture.h"

#include <cstring>

namespace pf {

RgbaImage captureFrame(const GpuContext& ctx, const RenderTarget& target,
                       const std::function<void(VkCommandBuffer, const RenderTarget&)>& record) {
    const VkExtent2D extent = target.extent;
    const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
    GpuResources scratch(ctx);
    Buffer readback = createHostBuffer(scratch, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        record(cmd, target);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent.width, extent.height, 1};
        vkCmdCopyImageToBuffer(cmd, target.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1,
                               &region);
        // Make the copy visible to the host read that follows the wait.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });

    RgbaImage image{extent.width, extent.height, std::vector<uint8_t>(bytes)};
    std::memcpy(image.pixels.data(), readback.mapped, bytes);
    return image;
}

} // namespace pf
