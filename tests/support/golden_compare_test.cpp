// The golden-image helper must detect what it is meant to detect.
#include "golden.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace pf::test {
namespace {

RgbaImage solid(uint32_t w, uint32_t h, uint8_t r, uint8_t g, uint8_t b) {
    RgbaImage image{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
    for (size_t p = 0; p < image.pixels.size(); p += 4) {
        image.pixels[p] = r;
        image.pixels[p + 1] = g;
        image.pixels[p + 2] = b;
        image.pixels[p + 3] = 255;
    }
    return image;
}

TEST(GoldenCompare, IdenticalImagesHaveNoFailingPixelsAndInfinitePsnr) {
    const RgbaImage a = solid(8, 8, 10, 20, 30);
    const ImageDiff diff = compareImages(a, a, 0);
    EXPECT_TRUE(diff.sameSize);
    EXPECT_EQ(diff.failingPixels, 0u);
    EXPECT_TRUE(std::isinf(diff.psnr));
}

TEST(GoldenCompare, DifferencesWithinToleranceDoNotFail) {
    const ImageDiff diff = compareImages(solid(8, 8, 10, 20, 30), solid(8, 8, 14, 20, 30), 5);
    EXPECT_EQ(diff.failingPixels, 0u);
    EXPECT_EQ(diff.maxChannelDelta, 4);
    EXPECT_NEAR(diff.psnr, 10.0 * std::log10(255.0 * 255.0 / (16.0 / 3.0)), 1e-9);
}

TEST(GoldenCompare, OnePixelBeyondToleranceIsCounted) {
    const RgbaImage expected = solid(10, 10, 100, 100, 100);
    RgbaImage actual = expected;
    actual.pixels[(3 * 10 + 4) * 4 + 1] = 120; // green of pixel (4, 3)
    const ImageDiff diff = compareImages(actual, expected, 5);
    EXPECT_EQ(diff.failingPixels, 1u);
    EXPECT_DOUBLE_EQ(diff.failingFraction, 0.01);
    EXPECT_EQ(diff.maxChannelDelta, 20);
}

TEST(GoldenCompare, SizeMismatchIsReported) {
    EXPECT_FALSE(compareImages(solid(4, 4, 0, 0, 0), solid(4, 5, 0, 0, 0), 5).sameSize);
}

TEST(GoldenCompare, FailureWritesActualAndDiffImages) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "golden_compare_test";
    fs::remove_all(dir);
    fs::create_directories(dir / "goldens");
    writePng((dir / "goldens" / "square.png").string(), solid(6, 6, 0, 0, 0));

    const ::testing::AssertionResult result = matchesGolden(solid(6, 6, 255, 0, 0), "square", ImageTolerance{5, 0.0},
                                                            (dir / "goldens").string(), dir.string());
    EXPECT_FALSE(result);
    ASSERT_TRUE(fs::exists(dir / "square-actual.png"));
    ASSERT_TRUE(fs::exists(dir / "square-diff.png"));
    const RgbaImage diffImage = readPng((dir / "square-diff.png").string());
    EXPECT_EQ(diffImage.pixels[0], 255); // failing pixels are red
    EXPECT_EQ(diffImage.pixels[1], 0);
}

TEST(GoldenCompare, MissingGoldenFailsWithInstructions) {
    const ::testing::AssertionResult result = matchesGolden(solid(2, 2, 0, 0, 0), "does_not_exist", ImageTolerance{},
                                                            PLANTFIELD_TEST_OUTPUT_DIR, PLANTFIELD_TEST_OUTPUT_DIR);
    EXPECT_FALSE(result);
    EXPECT_NE(std::string(result.message()).find("PLANTFIELD_UPDATE_GOLDENS"), std::string::npos);
}

} // namespace
} // namespace pf::test
