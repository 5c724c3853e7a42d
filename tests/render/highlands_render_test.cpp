// data/scenes/highlands.json rendered headless (the L-system landscapes of
// the clouds-and-mountains chapter, §21–24, with the forest): the massif of L-system peaks behind the
// valley's forest under the three layouts of L-system clouds, casting their
// shadows, against goldens at the field's tolerance (kFieldTolerance).
#include "field_render.h"
#include "golden.h"
#include "gpu_test.h"

#include <gtest/gtest.h>

namespace pf::test {
namespace {

class HighlandsRenderTest : public GpuTest {};

// t = 0: from above the valley's broadleaf forest toward the massif, the
// clouds over its summits.
TEST_F(HighlandsRenderTest, ValleyViewMatchesGolden) {
    const FieldShotResult r = renderField(ctx, {.scene = "highlands.json", .time = 0.0});
    EXPECT_GT(r.stats.plantsPerLod[LOD_IMPOSTOR], 1000u) << "the valley's far forest should be impostors";
    EXPECT_TRUE(matchesGolden(r.image, "highlands_valley_640x360", kFieldTolerance, PLANTFIELD_GOLDEN_DIR,
                              PLANTFIELD_TEST_OUTPUT_DIR));
}

// t = 15: between the peaks, spruce on the flanks, a cloud's shadow on the
// mountainside, the clouds drifted 15 s downwind.
TEST_F(HighlandsRenderTest, FlanksViewMatchesGolden) {
    const FieldShotResult r = renderField(ctx, {.scene = "highlands.json", .time = 15.0});
    EXPECT_TRUE(matchesGolden(r.image, "highlands_flanks_640x360", kFieldTolerance, PLANTFIELD_GOLDEN_DIR,
                              PLANTFIELD_TEST_OUTPUT_DIR));
}

} // namespace
} // namespace pf::test
