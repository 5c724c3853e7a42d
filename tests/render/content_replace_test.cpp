// replaceFieldContent (engine/field/field_renderer.h), as plantfield --watch
// swaps a rebuilt field into the window's live renderer: after frames of one
// field, the replaced renderer draws the new field bit for bit as a fresh
// renderer of it does; a replacement that cannot be built leaves the old
// renderer drawing as before. Validation is on (GpuTest).
#include "field_render.h"
#include "gpu_test.h"

#include "engine/field/impostor_atlas.h"
#include "shaders/shared/impostor_frame.h"

#include <gtest/gtest.h>

namespace pf::test {
namespace {

class ContentReplaceTest : public GpuTest {
protected:
    static FieldContent contentOf(const std::string& scene) {
        return buildFieldContent(loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/" + scene));
    }

    // A view of test_small.json's camera path at t.
    static FieldView viewAt(const Scene& scene, double t, bool firstFrame) {
        FieldView view;
        view.camera = cameraAt(scene.camera, t);
        view.time = float(t);
        view.deltaTime = firstFrame ? 0.0f : 0.1f;
        view.firstFrame = firstFrame;
        return view;
    }

    RgbaImage frame(FieldRenderer& renderer, const RenderTarget& target, const FieldView& view) {
        renderer.setView(view, kSize);
        return captureFrame(ctx, target, [&](VkCommandBuffer cmd, const RenderTarget& t) { renderer.record(cmd, t); });
    }

    static constexpr VkExtent2D kSize{160, 120};
};

TEST_F(ContentReplaceTest, AReplacedRendererDrawsWhatAFreshOneDraws) {
    const FieldContent before = contentOf("test_culling.json"), after = contentOf("test_small.json");
    const Scene& scene = after.scene;
    auto live = std::make_unique<FieldRenderer>(ctx, before, FieldRenderSettings{});
    RenderTarget target = createRenderTarget(ctx, kSize, live->antialiasing());
    for (int i = 0; i < 3; ++i) frame(*live, target, viewAt(scene, 0.1 * i, i == 0));
    const RgbaImage old = frame(*live, target, viewAt(scene, 0.3, false));

    replaceFieldContent(live, after);
    EXPECT_EQ(live->content().plants.size(), after.plants.size());
    const RgbaImage replaced = frame(*live, target, viewAt(scene, 0.3, true));
    live.reset();

    FieldRenderer fresh(ctx, after, FieldRenderSettings{});
    const RgbaImage expected = frame(fresh, target, viewAt(scene, 0.3, true));
    destroyRenderTarget(target);

    ASSERT_EQ(replaced.pixels.size(), size_t(kSize.width * kSize.height * 4));
    EXPECT_TRUE(replaced.pixels == expected.pixels) << "the replaced renderer draws other pixels than a fresh one";
    EXPECT_FALSE(replaced.pixels == old.pixels) << "the replacement draws the old field";
}

TEST_F(ContentReplaceTest, AFailedReplacementKeepsTheOldRendererDrawing) {
    const FieldContent content = contentOf("test_small.json");
    auto live = std::make_unique<FieldRenderer>(ctx, content, FieldRenderSettings{});
    RenderTarget target = createRenderTarget(ctx, kSize, live->antialiasing());
    const RgbaImage first = frame(*live, target, viewAt(content.scene, 1.0, true));

    // More species than the impostor atlas holds models (engine/field/impostor_sources.h): refused.
    FieldContent tooManySpecies = content;
    PlantModelPool& pool = tooManySpecies.models;
    const uint32_t capacity = ctx.properties.limits.maxImageArrayLayers / (ImpostorSettings{}.frames * IMPOSTOR_RINGS);
    while (pool.firstModel.size() <= capacity) {
        pool.firstModel.push_back(uint32_t(pool.models.size()));
        pool.models.push_back(pool.models.front());
    }
    const FieldRenderer* kept = live.get();
    EXPECT_THROW(replaceFieldContent(live, std::move(tooManySpecies)), SceneError);
    ASSERT_EQ(live.get(), kept);
    const RgbaImage again = frame(*live, target, viewAt(content.scene, 1.0, true));
    destroyRenderTarget(target);
    EXPECT_TRUE(again.pixels == first.pixels);
}

} // namespace
} // namespace pf::test
