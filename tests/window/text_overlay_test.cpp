// The text overlay drawn over a cleared target: where text lands, that empty
// text changes nothing, and that odd input is safe.
#include "gpu_test.h"

#include "engine/image/image.h"
#include "engine/vk/target_pass.h"
#include "engine/window/text_overlay.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

namespace pf::test {
namespace {

constexpr VkExtent2D kExtent{256, 64};
// The panel area the overlay may touch for "FPS 60": the top-left corner.
constexpr uint32_t kPanelWidth = 128;
constexpr uint32_t kPanelHeight = 40;

class TextOverlayTest : public GpuTest {
protected:
    // Clears a target, leaves it as the renderer would (TRANSFER_SRC), draws
    // the overlay when `text` is given, and reads the pixels back.
    RgbaImage render(const std::string* text, VkExtent2D extent = kExtent) {
        GpuResources scratch(ctx);
        TextOverlay overlay = createTextOverlay(scratch);
        if (text) setOverlayText(overlay, *text);
        RenderTarget target = createRenderTarget(ctx, extent, {.method = AntialiasMethod::none});
        const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
        Buffer readback = createHostBuffer(scratch, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

        submitAndWait(ctx, [&](VkCommandBuffer cmd) {
            const VkImage image = target.color.image;
            // Stands in for the renderer: a render pass that only clears
            // (the image has no TRANSFER_DST usage for vkCmdClearColorImage),
            // leaving the image in TRANSFER_SRC as SceneRenderer::record does.
            imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
            beginColorOnlyRendering(cmd, target.color.view, VK_ATTACHMENT_LOAD_OP_CLEAR, extent,
                                    {{0.05f, 0.2f, 0.4f, 1.0f}});
            vkCmdEndRendering(cmd);
            imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
            if (text) recordTextOverlay(cmd, overlay, target);

            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {extent.width, extent.height, 1};
            vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
            // Make the copy visible to the host read after the wait.
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });

        RgbaImage image{extent.width, extent.height, std::vector<uint8_t>(bytes)};
        std::memcpy(image.pixels.data(), readback.mapped, bytes);
        destroyRenderTarget(target);
        return image;
    }
};

const uint8_t* pixelAt(const RgbaImage& image, uint32_t x, uint32_t y) {
    return &image.pixels[(size_t(y) * image.width + x) * 4];
}

TEST_F(TextOverlayTest, TextAppearsInTheTopLeftPanelOnly) {
    const RgbaImage cleared = render(nullptr);
    const std::string text = "FPS 60";
    const RgbaImage drawn = render(&text);
    std::filesystem::create_directories(PLANTFIELD_TEST_OUTPUT_DIR);
    writePng(std::string(PLANTFIELD_TEST_OUTPUT_DIR) + "/text_overlay_fps60.png", drawn);

    uint32_t textPixels = 0, shadowPixels = 0, changedOutsidePanel = 0;
    for (uint32_t y = 0; y < kExtent.height; ++y)
        for (uint32_t x = 0; x < kExtent.width; ++x) {
            const uint8_t* before = pixelAt(cleared, x, y);
            const uint8_t* after = pixelAt(drawn, x, y);
            if (std::memcmp(before, after, 4) == 0) continue;
            const bool inPanel = x >= kOverlayMargin && x < kPanelWidth && y >= kOverlayMargin && y < kPanelHeight;
            if (!inPanel) ++changedOutsidePanel;
            if (after[0] == 255 && after[1] == 255 && after[2] == 255) ++textPixels;
            if (after[0] == 0 && after[1] == 0 && after[2] == 0) ++shadowPixels;
        }
    EXPECT_EQ(changedOutsidePanel, 0u);
    // Six glyphs at scale 2 cover a few hundred pixels; each has a shadow.
    EXPECT_GT(textPixels, 100u);
    EXPECT_GT(shadowPixels, 30u);
}

// The vertex shader maps pixels through a viewport of its own, not the
// target's size: the same text covers the same pixels in any target.
TEST_F(TextOverlayTest, TextCoversTheSamePixelsInAnyTargetSize) {
    const std::string text = "12.3 ms\nLOD0 1200";
    const RgbaImage small = render(&text);
    const RgbaImage large = render(&text, {3 * kExtent.width, 5 * kExtent.height});
    uint32_t different = 0, drawn = 0;
    for (uint32_t y = 0; y < kExtent.height; ++y)
        for (uint32_t x = 0; x < kExtent.width; ++x) {
            if (std::memcmp(pixelAt(small, x, y), pixelAt(large, x, y), 4) != 0) ++different;
            if (pixelAt(small, x, y)[0] == 255) ++drawn;
        }
    EXPECT_GT(drawn, 100u);
    EXPECT_EQ(different, 0u);
}

TEST_F(TextOverlayTest, EmptyTextLeavesTheImageUnchanged) {
    const RgbaImage cleared = render(nullptr);
    const std::string empty;
    const RgbaImage drawn = render(&empty);
    EXPECT_TRUE(cleared.pixels == drawn.pixels);
}

TEST_F(TextOverlayTest, UnprintableAndOverlongTextIsSafe) {
    TextOverlay overlay = createTextOverlay(resources);
    setOverlayText(overlay, "tab\there \x80\xff\r\n");
    EXPECT_GT(overlay.rectCount, 0u);
    setOverlayText(overlay, std::string(10 * kMaxOverlayCharacters, 'W'));
    const uint32_t capped = overlay.rectCount;
    setOverlayText(overlay, std::string(kMaxOverlayCharacters, 'W'));
    EXPECT_EQ(overlay.rectCount, capped);
}

} // namespace
} // namespace pf::test
