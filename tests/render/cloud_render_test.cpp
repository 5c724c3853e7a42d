// The cloud pass end to end on lavapipe (data/scenes/test_clouds.json, one
// explosion cloud ahead of the camera): the cloud whitens and brightens the
// sky where it stands and leaves every other pixel as the frame without
// clouds has it, bit for bit; a view away from it is the cloudless frame;
// it drifts with the wind; the same frame twice is the same pixels; with
// occlusion culling (the colour pass in two renderings) and with MSAA the
// clouds are drawn over the whole frame as well; a cloud's shadow darkens
// the ground under it and moves on with the wind.
#include "engine/field/field_renderer.h"
#include "engine/scene/cloud_billboards.h"
#include "engine/scene/cloud_spheres.h"
#include "engine/vk/capture.h"
#include "gpu_test.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace pf::test {
namespace {

constexpr VkExtent2D kSize{320, 180};

Scene cloudScene() { return loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_clouds.json"); }

Scene withoutClouds(Scene scene) {
    scene.clouds.clear();
    return scene;
}

RgbaImage renderFrame(const GpuContext& ctx, const Scene& scene, const Camera& camera, float time,
                      const FieldRenderSettings& settings = {}) {
    FieldRenderer renderer(ctx, buildFieldContent(scene), settings);
    RenderTarget target = createRenderTarget(ctx, kSize, renderer.antialiasing());
    FieldView view;
    view.camera = camera;
    view.time = time;
    renderer.setView(view, kSize);
    RgbaImage image =
        captureFrame(ctx, target, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer.record(cmd, t); });
    destroyRenderTarget(target);
    return image;
}

// The pixels (x0, y0, x1, y1), a few wider for FXAA, that the boxes around
// the spheres (moved by the wind for `time`) cover on screen.
glm::ivec4 screenBox(const Scene& scene, const Camera& camera, float time) {
    const glm::mat4 viewProj = makeFrameUniforms(camera, environmentOf(scene), {kSize.width, kSize.height}, 0).viewProj;
    const glm::vec3 drift = meanWindVelocity(scene.wind) * time;
    glm::vec2 low(1e9f), high(-1e9f);
    for (const Cloud& cloud : scene.clouds)
        for (const CloudSphere& sphere : cloud.spheres)
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
                const glm::vec4 clip = viewProj * glm::vec4(sphere.centre + drift + sign * sphere.radius, 1.0f);
                EXPECT_GT(clip.w, 0.0f) << "the cloud is ahead of the camera";
                const glm::vec2 ndc = glm::vec2(clip) / clip.w;
                const glm::vec2 pixel((ndc.x + 1.0f) * 0.5f * float(kSize.width),
                                      (1.0f - ndc.y) * 0.5f * float(kSize.height));
                low = glm::min(low, pixel);
                high = glm::max(high, pixel);
            }
    return glm::ivec4(glm::floor(low) - 3.0f, glm::ceil(high) + 3.0f);
}

struct CloudDifference {
    uint32_t changed = 0;        // pixels the cloud changed
    uint32_t changedOutside = 0; // of them, outside its screen box
    double brighter = 0.0;       // mean rise of the darkest channel over the changed pixels (whiter and brighter)
    double spreadDrop = 0.0;     // mean drop of max − min channel over them (less blue: whiter)
    double centreX = 0.0;        // mean column of the changed pixels
};

CloudDifference difference(const RgbaImage& clouds, const RgbaImage& clear, const glm::ivec4& box) {
    CloudDifference d;
    for (uint32_t y = 0; y < clouds.height; ++y)
        for (uint32_t x = 0; x < clouds.width; ++x) {
            const size_t i = (size_t(y) * clouds.width + x) * 4;
            const uint8_t* a = &clouds.pixels[i];
            const uint8_t* b = &clear.pixels[i];
            if (std::equal(a, a + 4, b)) continue;
            ++d.changed;
            if (int(x) < box.x || int(y) < box.y || int(x) > box.z || int(y) > box.w) ++d.changedOutside;
            d.brighter += int(std::min({a[0], a[1], a[2]})) - int(std::min({b[0], b[1], b[2]}));
            d.spreadDrop += (int(std::max({b[0], b[1], b[2]})) - int(std::min({b[0], b[1], b[2]}))) -
                            (int(std::max({a[0], a[1], a[2]})) - int(std::min({a[0], a[1], a[2]})));
            d.centreX += x;
        }
    if (d.changed) {
        d.brighter /= d.changed;
        d.spreadDrop /= d.changed;
        d.centreX /= d.changed;
    }
    return d;
}

class CloudRenderTest : public GpuTest {};

TEST_F(CloudRenderTest, TheCloudWhitensItsPartOfTheSkyAndNothingElse) {
    const Scene scene = cloudScene();
    ASSERT_EQ(scene.clouds.size(), 1u);
    const Camera camera = cameraAt(scene.camera, 0.0);
    const RgbaImage clouds = renderFrame(ctx, scene, camera, 0.0f);
    const RgbaImage clear = renderFrame(ctx, withoutClouds(scene), camera, 0.0f);
    const CloudDifference d = difference(clouds, clear, screenBox(scene, camera, 0.0f));
    EXPECT_GT(d.changed, kSize.width * kSize.height / 40) << "the cloud covers a part of the frame";
    EXPECT_EQ(d.changedOutside, 0u) << "pixels away from the cloud are the cloudless frame's, bit for bit";
    EXPECT_GT(d.brighter, 20.0) << "white cloud over blue sky: the darkest channel rises";
    EXPECT_GT(d.spreadDrop, 10.0) << "and the colour is less saturated";
}

TEST_F(CloudRenderTest, AViewAwayFromTheCloudIsTheCloudlessFrame) {
    const Scene scene = cloudScene();
    Camera away = cameraAt(scene.camera, 0.0);
    away.target = away.position + glm::vec3(0.0f, -0.3f, 1.0f); // looking south, at the ground; the cloud is north
    EXPECT_TRUE(renderFrame(ctx, scene, away, 0.0f).pixels ==
                renderFrame(ctx, withoutClouds(scene), away, 0.0f).pixels);
}

TEST_F(CloudRenderTest, TheCloudDriftsWithTheWindAndFramesRepeat) {
    const Scene scene = cloudScene(); // 3 m/s toward +x (east): to the right of a camera looking north
    const Camera camera = cameraAt(scene.camera, 0.0);
    const float later = 10.0f;
    const RgbaImage first = renderFrame(ctx, scene, camera, later);
    EXPECT_TRUE(first.pixels == renderFrame(ctx, scene, camera, later).pixels) << "same time and view, same pixels";
    const CloudDifference atStart =
        difference(renderFrame(ctx, scene, camera, 0.0f), renderFrame(ctx, withoutClouds(scene), camera, 0.0f),
                   screenBox(scene, camera, 0.0f));
    const CloudDifference atLater =
        difference(first, renderFrame(ctx, withoutClouds(scene), camera, later), screenBox(scene, camera, later));
    EXPECT_EQ(atLater.changedOutside, 0u) << "the cloud is where the wind has taken it";
    EXPECT_GT(atLater.centreX, atStart.centreX + 3.0) << "30 m east in 10 s, at about 180 m";
}

// The clouds come after the late phase's plants: the frame is the one
// without occlusion culling, bit for bit, as for plants alone.
TEST_F(CloudRenderTest, OcclusionCullingDrawsTheSameClouds) {
    const Scene scene = cloudScene();
    const Camera camera = cameraAt(scene.camera, 0.0);
    FieldRenderSettings occlusion;
    occlusion.occlusionCulling = true;
    EXPECT_TRUE(renderFrame(ctx, scene, camera, 0.0f, occlusion).pixels ==
                renderFrame(ctx, scene, camera, 0.0f).pixels);
}

// With 4× MSAA the cloud pipeline draws into the multisampled image.
TEST_F(CloudRenderTest, MultisampledFramesDrawTheCloud) {
    const Scene scene = cloudScene();
    const Camera camera = cameraAt(scene.camera, 0.0);
    FieldRenderSettings msaa;
    msaa.antialiasing.method = AntialiasMethod::msaa;
    const CloudDifference d =
        difference(renderFrame(ctx, scene, camera, 0.0f, msaa),
                   renderFrame(ctx, withoutClouds(scene), camera, 0.0f, msaa), screenBox(scene, camera, 0.0f));
    EXPECT_GT(d.changed, kSize.width * kSize.height / 40);
    EXPECT_EQ(d.changedOutside, 0u);
    EXPECT_GT(d.brighter, 20.0);
}

// The cloud moved so that the sun's ray through its middle (about 25 m up)
// meets the ground at the origin; a camera 6 m above the origin looks
// straight down into its shadow. Twenty seconds later the wind (3 m/s
// east) has carried the shadow out of view: the frame is the one without.
TEST_F(CloudRenderTest, AShadowDarkensTheGroundAndMovesOnWithTheWind) {
    Scene casting = cloudScene();
    const glm::vec3 sun = sunDirection(environmentOf(casting));
    Cloud& cloud = casting.clouds[0];
    ASSERT_TRUE(cloud.shadow);
    cloud.spheres = cloudSpheres(cloud.lsystem, cloud.seed, 30.0f,
                                 glm::vec3(sun.x, 0, sun.z) * (25.0f / sun.y) + glm::vec3(0, 10, 0));
    Scene quiet = casting;
    quiet.clouds[0].shadow = false;
    Camera down;
    down.position = {0.0f, 6.0f, 0.01f};
    down.target = {0.0f, 0.0f, 0.0f};
    down.fovYDegrees = 40.0f;

    const RgbaImage shadowed = renderFrame(ctx, casting, down, 0.0f);
    const RgbaImage lit = renderFrame(ctx, quiet, down, 0.0f);
    const size_t centre = (size_t(kSize.height / 2) * kSize.width + kSize.width / 2) * 4;
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(shadowed.pixels[centre + c] + 15, lit.pixels[centre + c]) << "channel " << c << " is not in shadow";
    EXPECT_TRUE(renderFrame(ctx, casting, down, 20.0f).pixels == renderFrame(ctx, quiet, down, 20.0f).pixels)
        << "the shadow has moved on";
}

} // namespace
} // namespace pf::test
