// The validation check itself must work, or every other GPU test proves nothing.
#include "gpu_test.h"

#include <gtest/gtest.h>

namespace pf::test {
namespace {

using ValidationTest = GpuTest;

TEST_F(ValidationTest, InvalidCallIsCaughtAndReported) {
    // A buffer with no usage flags violates VUID-VkBufferCreateInfo-usage-requiredbitmask;
    // lavapipe still creates it, so the call is harmless to the driver.
    ctx.validationLog->echoToStderr = false;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 64;
    info.usage = 0;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(ctx.device, &info, nullptr, &buffer);
    if (buffer) vkDestroyBuffer(ctx.device, buffer, nullptr);

    const std::vector<std::string> messages = ctx.validationLog->snapshot();
    ASSERT_FALSE(messages.empty()) << "the validation layer reported nothing for an invalid call";
    EXPECT_GE(ctx.validationLog->errorCount, 1u);
    EXPECT_NE(messages.front().find("VUID-VkBufferCreateInfo-usage"), std::string::npos) << messages.front();
    // Expected here; TearDown fails the test on anything else.
    ctx.validationLog->clear();
}

TEST_F(ValidationTest, ValidContextReportsNothing) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 64;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateBuffer(ctx.device, &info, nullptr, &buffer), VK_SUCCESS);
    vkDestroyBuffer(ctx.device, buffer, nullptr);
    EXPECT_EQ(ctx.validationLog->count(), 0u);
}

TEST(DeviceSelection, UnknownDeviceNameIsAClearError) {
    GpuContext ctx;
    GpuOptions options;
    options.deviceName = "no-such-gpu-xyz";
    try {
        createHeadlessContext(ctx, options);
        FAIL() << "a device was created for a name no device has";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("no-such-gpu-xyz"), std::string::npos) << e.what();
    }
    destroyContext(ctx);
}

} // namespace
} // namespace pf::test
