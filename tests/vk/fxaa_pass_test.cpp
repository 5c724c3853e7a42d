// The FXAA pass on synthetic sRGB images: edges are smoothed where they are
// and nowhere else, flat areas and smooth gradients pass unchanged, dark
// edges are found by their perceptual contrast, and two runs agree.
#include "gpu_test.h"
#include "image_upload.h"

#include "engine/vk/capture.h"
#include "engine/vk/fxaa_pass.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>

namespace pf::test {
namespace {

constexpr uint32_t kSide = 64;

// An opaque image whose RGB at each pixel is `value(x, y)` (sRGB bytes).
RgbaImage imageOf(const std::function<uint8_t(uint32_t x, uint32_t y)>& value) {
    RgbaImage image{kSide, kSide, std::vector<uint8_t>(size_t(kSide) * kSide * 4)};
    for (uint32_t y = 0; y < kSide; ++y)
        for (uint32_t x = 0; x < kSide; ++x) {
            uint8_t* p = &image.pixels[(size_t(y) * kSide + x) * 4];
            p[0] = p[1] = p[2] = value(x, y);
            p[3] = 255;
        }
    return image;
}

// A straight edge y = slope·x + offset through pixel centres: `above` where
// a centre lies above it (smaller y), `below` elsewhere.
struct Edge {
    float slope = 0.4f;
    float offset = 12.0f;
    uint8_t above = 255;
    uint8_t below = 0;

    // Signed distance in pixels of the centre of (x, y) from the line.
    float distance(uint32_t x, uint32_t y) const {
        return (float(y) + 0.5f - slope * (float(x) + 0.5f) - offset) / std::sqrt(1.0f + slope * slope);
    }
    RgbaImage image() const {
        return imageOf([&](uint32_t x, uint32_t y) { return distance(x, y) < 0.0f ? above : below; });
    }
};

uint8_t redAt(const RgbaImage& image, uint32_t x, uint32_t y) {
    return image.pixels[(size_t(y) * image.width + x) * 4];
}

// The largest difference of any RGB channel between two images of one size.
int largestDifference(const RgbaImage& a, const RgbaImage& b) {
    int largest = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        if (i % 4 != 3) largest = std::max(largest, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
    return largest;
}

class FxaaPassTest : public GpuTest {
protected:
    // Uploads `input` as the pass's sRGB source, runs the pass into the
    // colour image of a target made for FXAA (whose own FXAA pass is not
    // used) and reads that back.
    RgbaImage antialiased(const RgbaImage& input) {
        const VkExtent2D extent{input.width, input.height};
        const Image source =
            createImage(resources, {.extent = extent,
                                    .format = kColorFormat,
                                    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                    .flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT});
        const Buffer upload = createUploadBuffer(resources, input.pixels.data(), input.pixels.size());
        RenderTarget target = createRenderTarget(ctx, extent, {.method = AntialiasMethod::fxaa});
        const FxaaPass pass = createFxaaPass(resources, source, target.color);

        const RgbaImage output = captureFrame(ctx, target, [&](VkCommandBuffer cmd, const RenderTarget& t) {
            recordImageUpload(cmd, upload, source, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            imageBarrier(cmd, t.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
            recordFxaaPass(cmd, pass);
            imageBarrier(cmd, t.color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
        });
        destroyRenderTarget(target);
        return output;
    }
};

// Black and white: pixels whose centre is more than 1.5 px from the line keep
// their value exactly; grey ones (beyond 8/255 of either) lie along the line,
// in almost every column it crosses. A shallow edge (long steps: the search
// along it), a 45° one (one-pixel steps: the sub-pixel blend) and a steep one
// (searched down the columns).
TEST_F(FxaaPassTest, HardDiagonalEdgeGetsIntermediateValuesAlongTheEdgeOnly) {
    for (const Edge edge : {Edge{.slope = 0.4f, .offset = 12.0f}, Edge{.slope = 1.0f, .offset = 0.5f},
                            Edge{.slope = 2.5f, .offset = -40.0f}}) {
        SCOPED_TRACE("slope " + std::to_string(edge.slope));
        const RgbaImage input = edge.image();
        const RgbaImage output = antialiased(input);
        uint32_t grey = 0;
        for (uint32_t y = 0; y < kSide; ++y)
            for (uint32_t x = 0; x < kSide; ++x) {
                const uint8_t value = redAt(output, x, y);
                const float distance = std::abs(edge.distance(x, y));
                if (distance > 1.5f) {
                    ASSERT_EQ(value, redAt(input, x, y)) << "pixel " << x << "," << y << " away from the edge changed";
                } else if (value > 8 && value < 247) {
                    ++grey;
                }
            }
        // The edge crosses about kSide·√(1 + slope²)/max(1, slope) pixel
        // lines; at least one grey pixel for most of them.
        EXPECT_GT(grey, kSide / 2) << "too few smoothed pixels along the edge";
    }
}

// sRGB 0 against 64: a clear edge to the eye (perceptual contrast 0.25), but
// only 0.05 in linear luminance, under the pass's minimum contrast of 0.083.
// It must be smoothed: the contrast tests run on perceptual luma.
TEST_F(FxaaPassTest, DarkEdgeIsFoundByItsPerceptualContrast) {
    const Edge edge{.above = 64, .below = 0};
    const RgbaImage output = antialiased(edge.image());
    uint32_t between = 0;
    for (uint32_t y = 0; y < kSide; ++y)
        for (uint32_t x = 0; x < kSide; ++x) between += redAt(output, x, y) > 4 && redAt(output, x, y) < 60;
    EXPECT_GT(between, kSide / 2);
}

TEST_F(FxaaPassTest, FlatImagesAreUnchanged) {
    for (const uint8_t value : {uint8_t(0), uint8_t(1), uint8_t(100), uint8_t(188), uint8_t(255)}) {
        const RgbaImage input = imageOf([&](uint32_t, uint32_t) { return value; });
        EXPECT_LE(largestDifference(antialiased(input), input), 1) << "flat " << int(value);
    }
}

// Ramps of 4/255 a pixel across the image and down it (steps too small to be
// edges, and no feature a pixel wide): unchanged within 1/255.
TEST_F(FxaaPassTest, SmoothGradientsAreUnchanged) {
    const RgbaImage across = imageOf([](uint32_t x, uint32_t) { return uint8_t(4 * x); });
    EXPECT_LE(largestDifference(antialiased(across), across), 1);
    const RgbaImage down = imageOf([](uint32_t, uint32_t y) { return uint8_t(255 - 4 * y); });
    EXPECT_LE(largestDifference(antialiased(down), down), 1);
}

// Two runs over edges of every direction, steps and noise give the same bytes.
TEST_F(FxaaPassTest, TwoRunsAreIdentical) {
    const RgbaImage input = imageOf([](uint32_t x, uint32_t y) {
        const float dx = float(x) - 31.5f, dy = float(y) - 31.5f;
        const bool disc = dx * dx + dy * dy < 400.0f;
        const uint32_t hash = (x * 73856093u) ^ (y * 19349663u);
        return uint8_t((disc ? 220 : 30) + hash % 16);
    });
    const RgbaImage a = antialiased(input);
    const RgbaImage b = antialiased(input);
    EXPECT_TRUE(a.pixels == b.pixels);
    EXPECT_GT(largestDifference(a, input), 8) << "the disc's edge should have been smoothed";
}

} // namespace
} // namespace pf::test
