// The default forest rendered headless: goldens from a far and a near
// camera, culling from the frame statistics, determinism.
#include "field_render.h"
#include "golden.h"
#include "gpu_test.h"

#include <gtest/gtest.h>

namespace pf::test {
namespace {

class FieldRenderTest : public GpuTest {};

// t = 0 of the default path: 120 m out and 40 m up, the forest below.
TEST_F(FieldRenderTest, FarViewMatchesGolden) {
    const FieldShotResult r = renderField(ctx, {.scene = "default.json", .time = 0.0});
    EXPECT_GT(r.stats.plantsPerLod[LOD_IMPOSTOR], 1000u) << "the far field should be impostors";
    EXPECT_TRUE(matchesGolden(r.image, "field_far_640x360", kFieldTolerance, PLANTFIELD_GOLDEN_DIR,
                              PLANTFIELD_TEST_OUTPUT_DIR));
}

// Inside the forest, 5 m up among the trees: mesh plants, leaves and shadows.
TEST_F(FieldRenderTest, NearViewMatchesGolden) {
    Camera camera;
    camera.position = {-20.0f, 5.0f, 35.0f};
    camera.target = {5.0f, 4.0f, 10.0f};
    camera.fovYDegrees = 55.0f;
    camera.nearPlane = 0.1f;
    const FieldShotResult r = renderField(ctx, {.scene = "default.json", .camera = camera});
    EXPECT_GT(r.stats.plantsPerLod[LOD_FULL] + r.stats.plantsPerLod[LOD_REDUCED], 0u)
        << "near plants should be drawn as meshes, not impostors";
    EXPECT_TRUE(matchesGolden(r.image, "field_near_640x360", kFieldTolerance, PLANTFIELD_GOLDEN_DIR,
                              PLANTFIELD_TEST_OUTPUT_DIR));
}

// test_culling.json: 8 bushes ahead of a camera at the origin looking down
// -z, 6 behind it (one only 5 m behind). Only the ones ahead may be drawn.
TEST_F(FieldRenderTest, PlantsBehindTheCameraAreNeverDrawn) {
    const FieldShotResult ahead = renderField(ctx, {.scene = "test_culling.json", .size = {320, 180}});
    EXPECT_EQ(ahead.stats.instances, 14u);
    const uint32_t drawn = ahead.stats.plantsPerLod[0] + ahead.stats.plantsPerLod[1] + ahead.stats.plantsPerLod[2];
    EXPECT_EQ(drawn, 8u) << "every bush ahead and none behind";

    Camera turned;
    turned.position = {0.0f, 1.5f, 0.0f};
    turned.target = {0.0f, 1.0f, 10.0f};
    turned.fovYDegrees = 60.0f;
    const FieldShotResult behind =
        renderField(ctx, {.scene = "test_culling.json", .size = {320, 180}, .camera = turned});
    const uint32_t drawnTurned =
        behind.stats.plantsPerLod[0] + behind.stats.plantsPerLod[1] + behind.stats.plantsPerLod[2];
    EXPECT_EQ(drawnTurned, 6u) << "the row at z = 20 and the bush 5 m ahead; none of the other row";

    Camera up;
    up.position = {0.0f, 1.5f, 0.0f};
    up.target = {0.0f, 50.0f, 0.1f};
    const FieldShotResult sky = renderField(ctx, {.scene = "test_culling.json", .size = {320, 180}, .camera = up});
    EXPECT_EQ(sky.stats.plantsPerLod[0] + sky.stats.plantsPerLod[1] + sky.stats.plantsPerLod[2], 0u);
    EXPECT_EQ(sky.stats.triangles, 0u);
}

TEST_F(FieldRenderTest, SameInputsGiveIdenticalPixels) {
    const FieldShot shot{.scene = "default.json", .size = {320, 180}, .time = 12.5};
    const FieldShotResult a = renderField(ctx, shot);
    const FieldShotResult b = renderField(ctx, shot);
    ASSERT_EQ(a.image.pixels.size(), size_t(320 * 180 * 4));
    EXPECT_TRUE(a.image.pixels == b.image.pixels);
    EXPECT_EQ(a.stats.triangles, b.stats.triangles);
}

TEST_F(FieldRenderTest, TooLargeImageIsRejected) {
    const uint32_t tooLarge = ctx.properties.limits.maxImageDimension2D + 1;
    EXPECT_THROW(createRenderTarget(ctx, {tooLarge, 16}, {}), std::runtime_error);
    EXPECT_THROW(createRenderTarget(ctx, {0, 16}, {}), std::runtime_error);
}

} // namespace
} // namespace pf::test

namespace pf::test {
namespace {

// gust.json: full-detail plants in a strong gusty wind. At t = 0 they stand
// at rest; at t = 3 s they have moved, the same way on every run.
TEST_F(FieldRenderTest, MovingForestIsDeterministicAndMoves) {
    const FieldShot rest{.scene = "gust.json", .size = {320, 240}, .time = 0.0};
    FieldShot windy = rest;
    windy.time = 3.0;
    const FieldShotResult a = renderField(ctx, windy);
    const FieldShotResult b = renderField(ctx, windy);
    const FieldShotResult still = renderField(ctx, rest);
    ASSERT_GT(a.stats.plantsPerLod[LOD_FULL], 0u) << "the gust scene is meant to be seen at full detail";
    EXPECT_TRUE(a.image.pixels == b.image.pixels) << "two captures of the moving forest at t = 3 s differ";
    size_t moved = 0;
    for (size_t i = 0; i < a.image.pixels.size(); i += 4)
        moved += std::abs(a.image.pixels[i + 1] - still.image.pixels[i + 1]) > 24;
    EXPECT_GT(moved, 200u) << "the wind should have moved leaves and twigs by t = 3 s";
}

} // namespace
} // namespace pf::test
