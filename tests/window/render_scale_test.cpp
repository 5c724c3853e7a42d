// Dynamic resolution for the window (engine/window/render_scale.h): CPU only.
#include "engine/window/render_scale.h"

#include <gtest/gtest.h>

namespace pf {
namespace {

// Feeds `frames` frames of `ms` each; returns how many changed the scale.
int feed(RenderScaleState& state, const RenderScaleSettings& settings, double ms, int frames) {
    int changes = 0;
    for (int i = 0; i < frames; ++i) changes += updateRenderScale(state, settings, ms) ? 1 : 0;
    return changes;
}

TEST(RenderScale, SlowFramesLowerTheScaleInStepsDownToTheMinimum) {
    const RenderScaleSettings settings;
    RenderScaleState state = startRenderScale(settings);
    EXPECT_FLOAT_EQ(state.scale, 1.0f);
    // Fewer slow frames in a row than settleFrames change nothing.
    EXPECT_EQ(feed(state, settings, 80.0, int(settings.settleFrames) - 1), 0);
    EXPECT_FLOAT_EQ(state.scale, 1.0f);
    // Slightly slow: one step (1 · √(66.7 / 80) = 0.91).
    EXPECT_EQ(feed(state, settings, 80.0, 1), 1);
    EXPECT_FLOAT_EQ(state.scale, 1.0f - settings.step);
    feed(state, settings, 300.0, 100);
    EXPECT_FLOAT_EQ(state.scale, settings.minScale);
    EXPECT_EQ(feed(state, settings, 300.0, 20), 0) << "never below the minimum";
}

// Far too slow: as many steps down at once as the pixels ask for, judged by
// the fastest frame of the run (one quick frame among slow ones).
TEST(RenderScale, AFarTooSlowRunDropsSeveralStepsAtOnce) {
    const RenderScaleSettings settings;
    RenderScaleState state = startRenderScale(settings);
    // √(66.7 / 150) = 0.667: three steps, to 0.625; the 400 ms frames do not count.
    EXPECT_FALSE(updateRenderScale(state, settings, 400.0));
    EXPECT_FALSE(updateRenderScale(state, settings, 150.0));
    EXPECT_FALSE(updateRenderScale(state, settings, 400.0));
    EXPECT_TRUE(updateRenderScale(state, settings, 400.0));
    EXPECT_FLOAT_EQ(state.scale, 0.625f);
    // Far slower still: down to the minimum at once, not below.
    EXPECT_EQ(feed(state, settings, 2000.0, int(settings.settleFrames)), 1);
    EXPECT_FLOAT_EQ(state.scale, settings.minScale);
}

TEST(RenderScale, FastFramesRaiseItBackToTheWholeWindow) {
    RenderScaleSettings settings;
    settings.scale = 0.5f;
    RenderScaleState state = startRenderScale(settings);
    EXPECT_FLOAT_EQ(state.scale, 0.5f);
    feed(state, settings, 10.0, 100);
    EXPECT_FLOAT_EQ(state.scale, 1.0f);
    EXPECT_EQ(feed(state, settings, 10.0, 20), 0) << "never above 1";
}

TEST(RenderScale, HoldsWhereOneStepUpWouldMissTheTarget) {
    RenderScaleSettings settings;
    settings.scale = 0.75f;
    RenderScaleState state = startRenderScale(settings);
    // Within the target, but (0.875 / 0.75)² × 55 ms = 75 ms would not be.
    EXPECT_EQ(feed(state, settings, 55.0, 50), 0);
    EXPECT_FLOAT_EQ(state.scale, 0.75f);
    // An interrupted run of slow frames does not count.
    for (int i = 0; i < 20; ++i) {
        EXPECT_FALSE(updateRenderScale(state, settings, 300.0));
        EXPECT_FALSE(updateRenderScale(state, settings, 55.0));
    }
    EXPECT_FLOAT_EQ(state.scale, 0.75f);
}

TEST(RenderScale, ACpuDeviceStartsAtTheMinimumAndOthersAtTheWholeWindow) {
    const RenderScaleSettings cpu = dynamicRenderScaleFor(VK_PHYSICAL_DEVICE_TYPE_CPU);
    EXPECT_TRUE(cpu.dynamic);
    EXPECT_FLOAT_EQ(startRenderScale(cpu).scale, cpu.minScale);
    for (const VkPhysicalDeviceType gpu : {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
                                           VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU, VK_PHYSICAL_DEVICE_TYPE_OTHER}) {
        EXPECT_TRUE(dynamicRenderScaleFor(gpu).dynamic);
        EXPECT_FLOAT_EQ(startRenderScale(dynamicRenderScaleFor(gpu)).scale, 1.0f) << gpu;
    }
    // It rises from there as any dynamic scale does.
    RenderScaleState state = startRenderScale(cpu);
    feed(state, cpu, 10.0, 100);
    EXPECT_FLOAT_EQ(state.scale, 1.0f);
}

TEST(RenderScale, AFixedScaleNeverChanges) {
    RenderScaleSettings settings;
    settings.dynamic = false;
    settings.scale = 0.6f;
    RenderScaleState state = startRenderScale(settings);
    EXPECT_EQ(feed(state, settings, 1000.0, 50) + feed(state, settings, 1.0, 50), 0);
    EXPECT_FLOAT_EQ(state.scale, 0.6f);
}

TEST(RenderScale, ScaledExtentRoundsAndKeepsAPixel) {
    EXPECT_EQ(scaledExtent({1280, 720}, 0.5f).width, 640u);
    EXPECT_EQ(scaledExtent({1280, 720}, 0.5f).height, 360u);
    EXPECT_EQ(scaledExtent({1280, 720}, 0.875f).width, 1120u);
    EXPECT_EQ(scaledExtent({1281, 721}, 1.0f).height, 721u);
    EXPECT_EQ(scaledExtent({1, 1}, 0.25f).width, 1u);
}

} // namespace
} // namespace pf
