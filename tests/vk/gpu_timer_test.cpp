// GPU timestamp scopes: durations around real work, scope limits, and
// reading before anything was recorded.
#include "gpu_test.h"

#include "engine/vk/gpu_timer.h"
#include "engine/vk/resources.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace pf::test {
namespace {

class GpuTimerTest : public GpuTest {};

TEST_F(GpuTimerTest, TwoScopesAroundFillsReportTimesInOrder) {
    GpuTimer timer = createGpuTimer(ctx, 4);
    if (!timer.supported) {
        destroyGpuTimer(ctx, timer);
        GTEST_SKIP() << "the queue family writes no timestamps";
    }
    constexpr VkDeviceSize kBytes = 16u << 20;
    Buffer buffer =
        createBuffer(resources, kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);

    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        resetGpuTimer(cmd, timer);
        beginScope(cmd, timer, "first fill");
        vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 0x01010101u);
        endScope(cmd, timer);
        // The second fill overwrites the first: write-after-write.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        beginScope(cmd, timer, "second fill");
        vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 0x02020202u);
        endScope(cmd, timer);
    });

    const std::vector<ScopeTime> times = readGpuTimer(ctx, timer);
    ASSERT_EQ(times.size(), 2u);
    EXPECT_EQ(times[0].name, "first fill");
    EXPECT_EQ(times[1].name, "second fill");
    for (const ScopeTime& t : times) {
        EXPECT_TRUE(std::isfinite(t.milliseconds)) << t.name;
        EXPECT_GE(t.milliseconds, 0.0) << t.name;
        EXPECT_LT(t.milliseconds, 10000.0) << t.name; // a wrapped or garbage timestamp would be huge
    }
    destroyGpuTimer(ctx, timer);
}

// The scope for passes outside rendering records its dependency with no
// validation message and reports like any other, nested scopes inside it.
TEST_F(GpuTimerTest, ScopeBegunOutsideRenderingEnclosesItsInnerScopes) {
    GpuTimer timer = createGpuTimer(ctx, 2);
    if (!timer.supported) {
        destroyGpuTimer(ctx, timer);
        GTEST_SKIP() << "the queue family writes no timestamps";
    }
    Buffer buffer =
        createBuffer(resources, 16u << 20, VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        resetGpuTimer(cmd, timer);
        beginScopeOutsideRendering(cmd, timer, "pass");
        beginScope(cmd, timer, "fill");
        vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 0u);
        endScope(cmd, timer);
        endScope(cmd, timer);
    });
    const std::vector<ScopeTime> times = readGpuTimer(ctx, timer);
    ASSERT_EQ(times.size(), 2u);
    EXPECT_EQ(times[0].name, "pass");
    EXPECT_EQ(times[1].name, "fill");
    EXPECT_GE(times[0].milliseconds, times[1].milliseconds);
    destroyGpuTimer(ctx, timer);
}

TEST_F(GpuTimerTest, ScopesBeyondMaxScopesThrow) {
    GpuTimer timer = createGpuTimer(ctx, 2);
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        resetGpuTimer(cmd, timer);
        EXPECT_THROW(endScope(cmd, timer), std::logic_error);
        beginScope(cmd, timer, "outer");
        beginScope(cmd, timer, "inner");
        EXPECT_THROW(beginScope(cmd, timer, "one too many"), std::length_error);
        endScope(cmd, timer);
        endScope(cmd, timer);
    });
    const std::vector<ScopeTime> times = readGpuTimer(ctx, timer);
    if (timer.supported) {
        ASSERT_EQ(times.size(), 2u);
        EXPECT_EQ(times[0].name, "outer");
        EXPECT_EQ(times[1].name, "inner");
        EXPECT_GE(times[0].milliseconds, times[1].milliseconds); // outer encloses inner
    }
    destroyGpuTimer(ctx, timer);
    EXPECT_THROW(createGpuTimer(ctx, 0), std::invalid_argument);
}

TEST_F(GpuTimerTest, ReadingBeforeAnyFrameReturnsNothing) {
    GpuTimer timer = createGpuTimer(ctx, 4);
    EXPECT_TRUE(readGpuTimer(ctx, timer).empty());
    destroyGpuTimer(ctx, timer);
}

} // namespace
} // namespace pf::test
