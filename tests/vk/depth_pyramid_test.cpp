// The depth pyramid's reduction (engine/vk/depth_pyramid.h) against its CPU
// reference on synthetic depth buffers of odd, even and one-pixel-wide
// sizes: every level equal, and each texel the farthest depth of the pixels
// it covers.
#include "gpu_test.h"
#include "image_upload.h"

#include "engine/vk/depth_pyramid.h"
#include "engine/vk/resources.h"

#include <gtest/gtest.h>

#include <random>

namespace pf::test {
namespace {

class DepthPyramidTest : public GpuTest {
protected:
    // Uploads `depth` into a depth buffer, builds its pyramid and reads every level back.
    std::vector<std::vector<float>> reduceOnGpu(const std::vector<float>& depth, VkExtent2D extent) {
        const Image image =
            createImage(resources, {.extent = extent,
                                    .format = VK_FORMAT_D32_SFLOAT,
                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                             VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                    .aspect = VK_IMAGE_ASPECT_DEPTH_BIT});
        const DepthPyramid pyramid = createDepthPyramid(resources, image);
        const Buffer upload = createUploadBuffer(resources, depth.data(), depth.size() * 4);
        VkDeviceSize texels = 0;
        for (const VkExtent2D& e : pyramid.extents) texels += VkDeviceSize(e.width) * e.height;
        const Buffer download = createHostBuffer(resources, texels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            // As a rendering that stored it leaves it.
            recordImageUpload(cmd, upload, image, VK_IMAGE_ASPECT_DEPTH_BIT,
                              VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
            recordDepthPyramid(cmd, pyramid);
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
            VkDeviceSize offset = 0;
            for (uint32_t l = 0; l < pyramid.levels; ++l) {
                VkBufferImageCopy level{};
                level.bufferOffset = offset * 4;
                level.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1};
                level.imageExtent = {pyramid.extents[l].width, pyramid.extents[l].height, 1};
                vkCmdCopyImageToBuffer(cmd, pyramid.image.image, VK_IMAGE_LAYOUT_GENERAL, download.buffer, 1, &level);
                offset += VkDeviceSize(pyramid.extents[l].width) * pyramid.extents[l].height;
            }
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });
        std::vector<std::vector<float>> levels;
        const auto* words = static_cast<const float*>(download.mapped);
        for (const VkExtent2D& e : pyramid.extents) {
            levels.emplace_back(words, words + size_t(e.width) * e.height);
            words += size_t(e.width) * e.height;
        }
        return levels;
    }
};

std::vector<float> randomDepth(VkExtent2D extent, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> depth(size_t(extent.width) * extent.height);
    for (float& d : depth) d = unit(rng);
    return depth;
}

TEST_F(DepthPyramidTest, LevelsMatchTheCpuReference) {
    for (const VkExtent2D extent : {VkExtent2D{37, 23}, VkExtent2D{64, 64}, VkExtent2D{1, 5}, VkExtent2D{160, 90}}) {
        SCOPED_TRACE(std::to_string(extent.width) + "x" + std::to_string(extent.height));
        const std::vector<float> depth = randomDepth(extent, extent.width * 131 + extent.height);
        const std::vector<std::vector<float>> expected = depthPyramidOnCpu(depth, {extent.width, extent.height});
        const std::vector<std::vector<float>> actual = reduceOnGpu(depth, extent);
        ASSERT_EQ(actual.size(), expected.size());
        for (size_t l = 0; l < expected.size(); ++l) EXPECT_EQ(actual[l], expected[l]) << "level " << l;
        EXPECT_EQ(expected.back().size(), 1u) << "the top level is one texel";
    }
}

// Texel (x, y) of level l is the farthest of pixels (x, y)·2^(l+1) to (x + 1, y + 1)·2^(l+1) − 1.
TEST_F(DepthPyramidTest, TexelsHoldTheFarthestDepthOfTheirPixels) {
    const VkExtent2D extent{37, 23};
    const std::vector<float> depth = randomDepth(extent, 5);
    const std::vector<std::vector<float>> levels = depthPyramidOnCpu(depth, {extent.width, extent.height});
    const std::vector<PixelExtent> extents = depthPyramidExtents({extent.width, extent.height});
    for (size_t l = 0; l < levels.size(); ++l) {
        const uint32_t side = 2u << l;
        for (uint32_t y = 0; y < extents[l].height; ++y)
            for (uint32_t x = 0; x < extents[l].width; ++x) {
                float farthest = 0.0f;
                for (uint32_t py = y * side; py < std::min((y + 1) * side, extent.height); ++py)
                    for (uint32_t px = x * side; px < std::min((x + 1) * side, extent.width); ++px)
                        farthest = std::max(farthest, depth[size_t(py) * extent.width + px]);
                EXPECT_EQ(levels[l][size_t(y) * extents[l].width + x], farthest) << "level " << l;
            }
    }
}

} // namespace
} // namespace pf::test
