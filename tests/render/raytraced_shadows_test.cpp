// Ray-traced sun shadows (engine/field/raytraced_sun_pass.h) on the default
// forest from inside it: a golden, and the shadows against the shadow map's
// (plantfield --shadows raytraced against the default --shadows map).
#include "field_render.h"
#include "golden.h"
#include "gpu_test.h"

#include "engine/image/image.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace pf::test {
namespace {

class RaytracedShadowsTest : public GpuTest {};

// field_render_test.cpp's near view: 5 m up among the trees.
FieldShot nearShot(SunShadows shadows) {
    Camera camera;
    camera.position = {-20.0f, 5.0f, 35.0f};
    camera.target = {5.0f, 4.0f, 10.0f};
    camera.fovYDegrees = 55.0f;
    camera.nearPlane = 0.1f;
    return {.scene = "default.json", .size = {320, 180}, .camera = camera, .shadows = shadows};
}

// Green darkened by more than this (of 255) against the frame without
// shadows: the pixel is in the sun's shadow.
constexpr int kShadowedDarkening = 12;

std::vector<bool> shadowedPixels(const RgbaImage& lit, const RgbaImage& shadowed) {
    std::vector<bool> inShadow;
    for (int darkening : shadowDarkening(lit, shadowed)) inShadow.push_back(darkening > kShadowedDarkening);
    return inShadow;
}

TEST_F(RaytracedShadowsTest, NearViewMatchesGolden) {
    const FieldShotResult r = renderField(ctx, nearShot(SunShadows::raytraced));
    EXPECT_GT(r.stats.plantsPerLod[LOD_FULL] + r.stats.plantsPerLod[LOD_REDUCED], 0u);
    EXPECT_EQ(r.stats.shadowCastersPerLod[LOD_FULL], 0u) << "no shadow map is drawn";
    EXPECT_TRUE(matchesGolden(r.image, "field_near_raytraced_320x180", kFieldTolerance, PLANTFIELD_GOLDEN_DIR,
                              PLANTFIELD_TEST_OUTPUT_DIR));
}

// The same pixels are in shadow by either method but for the map's
// approximations: its bias, its 2×2 PCF, and the impostors it draws as
// their billboards' shadows where the rays meet the plants' meshes.
// Measured on lavapipe: intersection over union 0.855, and 0.859 against a
// map of 8192² texels (1.5 cm) — the difference is not the map's
// resolution. Without the leaf cards' cut-outs or the impostors' origins it
// falls to 0.61.
TEST_F(RaytracedShadowsTest, ShadowsAreWhereTheShadowMapPutsThem) {
    const RgbaImage lit = renderField(ctx, nearShot(SunShadows::none)).image;
    const RgbaImage mapped = renderField(ctx, nearShot(SunShadows::map)).image;
    const RgbaImage traced = renderField(ctx, nearShot(SunShadows::raytraced)).image;
    const std::vector<bool> byMap = shadowedPixels(lit, mapped), byRays = shadowedPixels(lit, traced);
    size_t map = 0, rays = 0, both = 0;
    for (size_t i = 0; i < byMap.size(); ++i) {
        map += byMap[i];
        rays += byRays[i];
        both += byMap[i] && byRays[i];
    }
    const double overlap = double(both) / double(map + rays - both); // intersection over union
    std::printf("shadowed pixels: map %zu, rays %zu, both %zu of %zu; intersection over union %.3f\n", map, rays, both,
                byMap.size(), overlap);
    EXPECT_GT(rays, byRays.size() / 10) << "the forest floor and the crowns are largely in shade";
    EXPECT_GT(overlap, 0.8);
    if (overlap <= 0.8) {
        writePng(std::string(PLANTFIELD_TEST_OUTPUT_DIR) + "/raytraced_shadows_map.png", mapped);
        writePng(std::string(PLANTFIELD_TEST_OUTPUT_DIR) + "/raytraced_shadows_rays.png", traced);
    }
}

// A window's frames change size (a resize, the render scale): a renderer
// that drew at one size draws the next frame at another as a fresh one does.
TEST_F(RaytracedShadowsTest, AFrameOfANewSizeIsAFreshRenderersFrame) {
    const FieldShot shot = nearShot(SunShadows::raytraced);
    FieldRenderSettings settings;
    settings.shadows = SunShadows::raytraced;
    FieldRenderer renderer(ctx, buildFieldContent(loadScene(PLANTFIELD_DATA_DIR "/scenes/" + shot.scene)), settings);
    FieldView view;
    view.camera = *shot.camera;
    RgbaImage resized;
    for (VkExtent2D size : {VkExtent2D{320, 180}, VkExtent2D{160, 90}}) {
        RenderTarget target = createRenderTarget(ctx, size, renderer.antialiasing());
        renderer.setView(view, size);
        resized =
            captureFrame(ctx, target, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer.record(cmd, t); });
        destroyRenderTarget(target);
    }
    const RgbaImage expected =
        renderField(ctx,
                    {.scene = shot.scene, .size = {160, 90}, .camera = shot.camera, .shadows = SunShadows::raytraced})
            .image;
    const ImageDiff diff = compareImages(resized, expected, 0);
    EXPECT_TRUE(diff.sameSize);
    EXPECT_EQ(diff.failingPixels, 0u) << "largest difference " << diff.maxChannelDelta;
}

// The rays start from what the frame draws before its colour pass.
TEST_F(RaytracedShadowsTest, OcclusionCullingIsRefused) {
    FieldRenderSettings settings;
    settings.shadows = SunShadows::raytraced;
    settings.occlusionCulling = true;
    try {
        FieldSequence sequence(ctx, "test_culling.json", {64, 64}, settings);
        ADD_FAILURE() << "the renderer was made";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("occlusion culling"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace pf::test
