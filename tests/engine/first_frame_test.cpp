// The built-in scene rendered headless: golden image, determinism, sizes.
#include "golden.h"
#include "gpu_test.h"

#include "engine/capture.h"
#include "engine/default_scene.h"

#include <gtest/gtest.h>

namespace pf::test {
namespace {

class FirstFrameTest : public GpuTest {
protected:
    RgbaImage render(VkExtent2D extent, double time = 0.0) {
        const DefaultScene scene = buildDefaultScene();
        SceneRenderer renderer(ctx, scene.geometry, VK_SAMPLE_COUNT_4_BIT);
        RenderTarget target = createRenderTarget(ctx, extent, renderer.samples());
        renderer.setFrameUniforms(
            makeFrameUniforms(defaultCameraAt(scene, time), scene.environment, extent, float(time)));
        RgbaImage image = captureFrame(ctx, renderer, target);
        destroyRenderTarget(ctx, target);
        return image;
    }
};

TEST_F(FirstFrameTest, MatchesGolden) {
    const RgbaImage image = render({640, 360});
    // lavapipe is deterministic for a fixed driver; the tolerance absorbs
    // rounding differences between LLVM versions.
    EXPECT_TRUE(matchesGolden(image, "first_frame_640x360", ImageTolerance{5, 0.001}, PLANTFIELD_GOLDEN_DIR,
                              PLANTFIELD_TEST_OUTPUT_DIR));
}

TEST_F(FirstFrameTest, SameInputsGiveIdenticalPixels) {
    const RgbaImage a = render({320, 180}, 1.5);
    const RgbaImage b = render({320, 180}, 1.5);
    ASSERT_EQ(a.pixels.size(), size_t(320 * 180 * 4));
    EXPECT_TRUE(a.pixels == b.pixels);
}

TEST_F(FirstFrameTest, ShowsSkyGroundAndPlant) {
    const RgbaImage image = render({320, 180});
    auto pixel = [&](uint32_t x, uint32_t y) {
        const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
        return std::array<int, 3>{p[0], p[1], p[2]};
    };
    const auto sky = pixel(160, 2);
    EXPECT_GT(sky[2], sky[0]) << "the top row should be blue sky";
    const auto ground = pixel(10, 175);
    EXPECT_GT(ground[1], ground[2]) << "the bottom corner should be green ground";
    // Some pixel in the middle column differs from both: the plant.
    int plantPixels = 0;
    for (uint32_t y = 0; y < image.height; ++y) {
        const auto p = pixel(160, y);
        if (p[0] > p[1] && p[0] > p[2]) ++plantPixels; // bark is reddish brown
    }
    EXPECT_GT(plantPixels, 10);
}

TEST_F(FirstFrameTest, TooLargeImageIsRejected) {
    const uint32_t tooLarge = ctx.properties.limits.maxImageDimension2D + 1;
    EXPECT_THROW(createRenderTarget(ctx, {tooLarge, 16}, VK_SAMPLE_COUNT_1_BIT), std::runtime_error);
    EXPECT_THROW(createRenderTarget(ctx, {0, 16}, VK_SAMPLE_COUNT_1_BIT), std::runtime_error);
}

} // namespace
} // namespace pf::test
