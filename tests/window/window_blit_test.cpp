// The window blit (engine/window/window_blit.h) into offscreen images of the
// swapchain's formats: a UNORM output filters the frame's sRGB-encoded bytes
// as they are, an sRGB one in linear light, and at the same size both copy
// every byte. Validation on.
#include "engine/vk/render_target.h"
#include "engine/window/window_blit.h"
#include "gpu_test.h"
#include "image_upload.h"

#include <cstring>

namespace pf::test {
namespace {

class WindowBlitTest : public GpuTest {
protected:
    // `pixels` (RGBA bytes, sRGB-encoded) as a frame of `source` size, blitted
    // into an image of `outputFormat` and `output` size; its bytes read back.
    std::vector<uint8_t> blit(const std::vector<uint8_t>& pixels, VkExtent2D source, VkFormat outputFormat,
                              VkExtent2D output) {
        GpuResources scratch(ctx);
        const Image frame = createImage(scratch, {.extent = source,
                                                  .format = kColorFormat,
                                                  .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                  .flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT});
        const Image target =
            createImage(scratch, {.extent = output,
                                  .format = outputFormat,
                                  .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
        const WindowBlit windowBlit = createWindowBlit(scratch, frame, outputFormat);
        const Buffer upload = createUploadBuffer(scratch, pixels.data(), pixels.size());
        const VkDeviceSize bytes = VkDeviceSize(output.width) * output.height * 4;
        const Buffer readback = createHostBuffer(scratch, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            recordImageUpload(cmd, upload, frame, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            imageBarrier(cmd, target.image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
            recordWindowBlit(cmd, windowBlit, target.view, output);
            imageBarrier(cmd, target.image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {output.width, output.height, 1};
            vkCmdCopyImageToBuffer(cmd, target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1,
                                   &region);
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });
        std::vector<uint8_t> result(bytes);
        std::memcpy(result.data(), readback.mapped, bytes);
        return result;
    }
};

// A black and a white pixel, the output twice as wide: its pixel centres
// fall at 1/4 and 3/4 between the two source texels' centres (the outer
// ones clamp to the edge texels).
const std::vector<uint8_t> kBlackWhite = {0, 0, 0, 255, 255, 255, 255, 255};

std::vector<int> redOf(const std::vector<uint8_t>& rgba) {
    std::vector<int> red;
    for (size_t i = 0; i < rgba.size(); i += 4) red.push_back(rgba[i]);
    return red;
}

TEST_F(WindowBlitTest, AUnormOutputFiltersTheEncodedBytes) {
    const std::vector<int> red = redOf(blit(kBlackWhite, {2, 1}, VK_FORMAT_R8G8B8A8_UNORM, {4, 1}));
    ASSERT_EQ(red.size(), 4u);
    const int expected[4] = {0, 64, 191, 255}; // 1/4 and 3/4 of 255, the mean of the bytes
    for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(red[i], expected[i], 1) << "pixel " << i;
}

TEST_F(WindowBlitTest, AnSrgbOutputFiltersInLinearLight) {
    const std::vector<int> red = redOf(blit(kBlackWhite, {2, 1}, VK_FORMAT_B8G8R8A8_SRGB, {4, 1}));
    ASSERT_EQ(red.size(), 4u);
    // 1/4 and 3/4 of the light, sRGB-encoded (BGRA: the red byte is third;
    // here every channel is the same).
    const int expected[4] = {0, 137, 225, 255};
    for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(red[i], expected[i], 2) << "pixel " << i;
}

TEST_F(WindowBlitTest, AtTheSameSizeEveryByteIsCopied) {
    std::vector<uint8_t> pixels;
    for (uint32_t i = 0; i < 8 * 4; ++i)
        for (const uint32_t channel : {i * 37u % 256u, i * 101u % 256u, i * 7u % 256u, 255u})
            pixels.push_back(uint8_t(channel));
    EXPECT_EQ(blit(pixels, {8, 4}, VK_FORMAT_R8G8B8A8_UNORM, {8, 4}), pixels);
    // An sRGB output decodes and encodes each texel again: the same bytes.
    EXPECT_EQ(blit(pixels, {8, 4}, VK_FORMAT_R8G8B8A8_SRGB, {8, 4}), pixels);
}

TEST_F(WindowBlitTest, ReadsThroughTheOutputsEncoding) {
    EXPECT_EQ(windowBlitSourceFormat(VK_FORMAT_B8G8R8A8_UNORM), VK_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(windowBlitSourceFormat(VK_FORMAT_R8G8B8A8_UNORM), VK_FORMAT_R8G8B8A8_UNORM);
    EXPECT_EQ(windowBlitSourceFormat(VK_FORMAT_B8G8R8A8_SRGB), kColorFormat);
    EXPECT_EQ(windowBlitSourceFormat(VK_FORMAT_R8G8B8A8_SRGB), kColorFormat);
}

} // namespace
} // namespace pf::test
