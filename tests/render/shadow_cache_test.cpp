// The cache of the sun's static shadow casters (engine/field/shadow_cache.h)
// in the renderer: kept while the camera moves a little, drawn again when it
// moves far, a frame drawn with it equal to the frame drawn from scratch,
// and the shadows of swaying plants still moving while it is kept.
#include "field_render.h"
#include "gpu_test.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace pf::test {
namespace {

class ShadowCacheTest : public GpuTest {};

// Frame i of a sequence: scene time t0 + i/30 s, as plantfield --frames --fps 30 takes them.
FieldView sequenceView(const Camera& camera, double t0, uint32_t i) {
    FieldView view;
    view.camera = camera;
    view.time = float(t0 + i / 30.0);
    view.deltaTime = i == 0 ? 0.0f : 1.0f / 30.0f;
    view.firstFrame = i == 0;
    return view;
}

// The camera moved `metres` along its view, flattened to the ground.
Camera movedAhead(const Camera& camera, float metres) {
    const glm::vec3 forward = camera.target - camera.position;
    const glm::vec3 step = glm::normalize(glm::vec3(forward.x, 0.0f, forward.z)) * metres;
    Camera moved = camera;
    moved.position += step;
    moved.target += step;
    return moved;
}

TEST_F(ShadowCacheTest, KeptWhileTheCameraMovesALittleAndDrawnAgainWhenItMovesFar) {
    FieldSequence sequence(ctx, "default.json", {320, 180});
    const Camera start = cameraAt(sequence.scene().camera, 0.0);
    uint32_t i = 0;
    auto rendersAfter = [&](const Camera& camera) {
        return sequence.frame(sequenceView(camera, 0.0, i++)).stats.shadowCacheRenders;
    };
    const FieldShotResult first = sequence.frame(sequenceView(start, 0.0, i++));
    EXPECT_EQ(first.stats.shadowCacheRenders, 1u);
    EXPECT_GT(first.stats.shadowCacheCasters, 500u) << "the forest below is held by the cache";
    EXPECT_EQ(rendersAfter(movedAhead(start, 2.0f)), 1u);
    EXPECT_EQ(rendersAfter(movedAhead(start, 6.0f)), 1u);
    EXPECT_EQ(rendersAfter(movedAhead(start, 30.0f)), 2u) << "30 m is past the cache's reach";
    EXPECT_EQ(rendersAfter(movedAhead(start, 32.0f)), 2u) << "kept again from there";
    Camera turned = movedAhead(start, 32.0f);
    turned.target = 2.0f * turned.position - turned.target;
    EXPECT_EQ(rendersAfter(turned), 3u) << "turned round, the square ahead of the camera leaves the cache";
}

// The near view of the goldens, then 6 m toward what it looks at over 6
// frames while the plants sway: the last frame drawn with the cache kept
// from the first equals the one whose map was drawn from scratch every frame.
TEST_F(ShadowCacheTest, FrameDrawnWithTheCacheEqualsTheMapDrawnFromScratch) {
    FieldRenderSettings fromScratch;
    fromScratch.shadowCache.reuse = false;
    FieldSequence cached(ctx, "default.json", {640, 360});
    FieldSequence scratch(ctx, "default.json", {640, 360}, fromScratch);
    Camera camera;
    camera.position = {-20.0f, 5.0f, 35.0f};
    camera.target = {5.0f, 4.0f, 10.0f};
    camera.fovYDegrees = 55.0f;
    camera.nearPlane = 0.1f;
    FieldShotResult a, b;
    constexpr uint32_t kFrames = 6;
    for (uint32_t i = 0; i < kFrames; ++i) {
        const FieldView view = sequenceView(movedAhead(camera, 1.2f * float(i)), 2.0, i);
        a = cached.frame(view);
        b = scratch.frame(view);
    }
    EXPECT_EQ(a.stats.shadowCacheRenders, 1u);
    EXPECT_EQ(b.stats.shadowCacheRenders, kFrames);
    EXPECT_GT(a.stats.shadowCastersPerLod[LOD_FULL] + a.stats.shadowCastersPerLod[LOD_REDUCED], 0u)
        << "the near trees are drawn every frame as meshes";
    const ImageDiff diff = compareImages(a.image, b.image, kFieldTolerance.channel);
    std::printf("cached against scratch after %u frames: %llu pixels beyond %d/255, largest %d, PSNR %.1f dB\n",
                kFrames, static_cast<unsigned long long>(diff.failingPixels), kFieldTolerance.channel,
                diff.maxChannelDelta, diff.psnr);
    EXPECT_TRUE(diff.sameSize);
    EXPECT_LE(diff.failingFraction, kFieldTolerance.failingPixelFraction);
}

// gust.json from its camera: while the cache is kept, the shadows the
// swaying tree and bushes cast move from one frame to the next.
TEST_F(ShadowCacheTest, ShadowsOfSwayingPlantsMoveWhileTheCacheIsKept) {
    FieldRenderSettings noShadows;
    noShadows.shadows = SunShadows::none;
    FieldSequence shadowed(ctx, "gust.json", {320, 240});
    FieldSequence lit(ctx, "gust.json", {320, 240}, noShadows);
    const Camera camera = cameraAt(shadowed.scene().camera, 0.0);
    std::vector<std::vector<int>> darkening;
    FieldShotResult last;
    for (uint32_t i = 0; i < 10; ++i) {
        const FieldView view = sequenceView(camera, 3.0, i);
        last = shadowed.frame(view);
        const FieldShotResult plain = lit.frame(view);
        if (i == 0 || i == 9) darkening.push_back(shadowDarkening(plain.image, last.image));
    }
    EXPECT_EQ(last.stats.shadowCacheRenders, 1u);
    EXPECT_GT(last.stats.shadowCastersPerLod[LOD_FULL], 0u);
    size_t moved = 0;
    for (size_t p = 0; p < darkening[0].size(); ++p) moved += std::abs(darkening[0][p] - darkening[1][p]) > 24;
    EXPECT_GT(moved, 100u) << "in 0.3 s of gale the shadows should have moved";
}

} // namespace
} // namespace pf::test
