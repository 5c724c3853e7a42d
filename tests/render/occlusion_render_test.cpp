// Occlusion culling end to end (docs/CULLING.md): frames drawn with it equal
// frames drawn without it, over sequences along the camera path (the early
// phase draws what the previous frame found visible) and from views where
// the terrain or nearer crowns hide plants, with FXAA and with MSAA; and the
// plants it hides are counted.
#include "field_render.h"
#include "golden.h"
#include "gpu_test.h"

#include "engine/scene/terrain.h"

#include <gtest/gtest.h>

#include <iostream>
#include <vector>

namespace pf::test {
namespace {

class OcclusionRenderTest : public GpuTest {};

constexpr VkExtent2D kSize{320, 180};

struct SequenceResult {
    uint32_t occluded = 0; // summed over the frames with occlusion culling
    uint32_t occludedWithout = 0;
};

// Draws `views` in order with one renderer with occlusion culling and one
// without; every frame must match.
SequenceResult expectSameFrames(const GpuContext& ctx, const std::vector<FieldView>& views,
                                const Antialiasing& antialiasing, const std::string& name) {
    FieldRenderSettings on, off;
    on.antialiasing = off.antialiasing = antialiasing;
    on.occlusionCulling = true;
    FieldSequence culled(ctx, "default.json", kSize, on);
    FieldSequence all(ctx, "default.json", kSize, off);
    SequenceResult result;
    for (size_t i = 0; i < views.size(); ++i) {
        SCOPED_TRACE(name + " frame " + std::to_string(i));
        const FieldShotResult a = culled.frame(views[i]);
        const FieldShotResult b = all.frame(views[i]);
        const ImageDiff diff = compareImages(a.image, b.image, kFieldTolerance.channel);
        EXPECT_LE(diff.failingFraction, kFieldTolerance.failingPixelFraction)
            << diff.failingPixels << " pixels differ, by up to " << diff.maxChannelDelta;
        EXPECT_LE(a.stats.visibleEntries(), b.stats.visibleEntries());
        EXPECT_EQ(a.stats.culled(), b.stats.culled() + a.stats.occluded) << "occluded plants are the only extra culled";
        result.occluded += a.stats.occluded;
        result.occludedWithout += b.stats.occluded;
    }
    std::cout << name << ": " << result.occluded << " plants occluded over " << views.size() << " frames\n";
    return result;
}

// Three bursts of frames a thirtieth of a second apart at points along the
// default camera path: each burst's first frame finds the previous burst's
// plants visible from elsewhere, the others their own previous frame's.
std::vector<FieldView> alongThePath(const Scene& scene) {
    std::vector<FieldView> views;
    for (double start : {0.0, 18.0, 30.0})
        for (int i = 0; i < 3; ++i) {
            FieldView v;
            v.time = float(start + i / 30.0);
            v.camera = cameraAt(scene.camera, v.time);
            v.firstFrame = views.empty();
            v.deltaTime = views.empty() ? 0.0f : 1.0f / 30.0f;
            views.push_back(v);
        }
    return views;
}

// Low over the ground, looking across: hills and nearer crowns hide most of
// the forest. The camera stands 1.7 m above the terrain at (x, z).
std::vector<FieldView> nearTheGround(const FieldContent& content, float x, float z, glm::vec3 toward) {
    std::vector<FieldView> views;
    for (int i = 0; i < 3; ++i) {
        FieldView v;
        v.camera.position = {x + i * 0.3f, heightAt(content.terrain, x, z) + 1.7f, z};
        v.camera.target = v.camera.position + toward;
        v.camera.fovYDegrees = 60.0f;
        v.camera.nearPlane = 0.1f;
        v.time = i / 30.0f;
        v.firstFrame = i == 0;
        v.deltaTime = i == 0 ? 0.0f : 1.0f / 30.0f;
        views.push_back(v);
    }
    return views;
}

TEST_F(OcclusionRenderTest, FramesAlongThePathMatchWithoutOcclusionCulling) {
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/default.json");
    const SequenceResult r = expectSameFrames(ctx, alongThePath(scene), {}, "fxaa");
    EXPECT_EQ(r.occludedWithout, 0u);
}

TEST_F(OcclusionRenderTest, ViewsNearTheGroundMatchAndHidePlants) {
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/default.json");
    const FieldContent content = buildFieldContent(scene);
    for (const Antialiasing aa : {Antialiasing{}, Antialiasing{.method = AntialiasMethod::msaa, .msaaSamples = 4}}) {
        const std::string name = antialiasMethodName(aa.method);
        const SequenceResult hill =
            expectSameFrames(ctx, nearTheGround(content, -100.0f, 100.0f, {60.0f, -2.0f, -60.0f}), aa, name + " hill");
        EXPECT_GT(hill.occluded, 0u) << "the terrain and the first trees hide plants";
        EXPECT_EQ(hill.occludedWithout, 0u);
        const SequenceResult crowns =
            expectSameFrames(ctx, nearTheGround(content, -20.0f, 35.0f, {25.0f, -1.0f, -25.0f}), aa, name + " crowns");
        EXPECT_GT(crowns.occluded, 0u) << "inside the forest nearer crowns hide farther plants";
    }
}

} // namespace
} // namespace pf::test
