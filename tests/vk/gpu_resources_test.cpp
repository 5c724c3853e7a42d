// GpuResources: what it counts and that it destroys everything once (the
// validation layer reports leaked or twice-destroyed objects at teardown).
#include "engine/vk/resources.h"
#include "gpu_test.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace pf::test {
namespace {

class GpuResourcesTest : public GpuTest {};

TEST_F(GpuResourcesTest, BytesAreTheMemoryOfWhatItOwnsUntilDestroyed) {
    GpuResources owner(ctx);
    EXPECT_EQ(owner.bytes(), 0u);
    const Buffer buffer = createHostBuffer(owner, 1000, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    const Image image = createImage(owner, {.extent = {64, 32},
                                            .format = VK_FORMAT_R8G8B8A8_UNORM,
                                            .usage = VK_IMAGE_USAGE_SAMPLED_BIT,
                                            .mipLevels = 3,
                                            .layers = 2,
                                            .viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY});
    createTexelView(owner, buffer, VK_FORMAT_R32_UINT);
    VkMemoryRequirements bufferMemory, imageMemory;
    vkGetBufferMemoryRequirements(ctx.device, buffer.buffer, &bufferMemory);
    vkGetImageMemoryRequirements(ctx.device, image.image, &imageMemory);
    EXPECT_EQ(owner.bytes(), bufferMemory.size + imageMemory.size);

    GpuResources moved = std::move(owner);
    EXPECT_EQ(owner.bytes(), 0u);
    EXPECT_EQ(moved.bytes(), bufferMemory.size + imageMemory.size);
    moved.destroy();
    EXPECT_EQ(moved.bytes(), 0u);
}

TEST_F(GpuResourcesTest, AnAllocationBeyondTheHeapIsAnErrorNotACrash) {
    VkDeviceSize largestHeap = 0;
    for (uint32_t i = 0; i < ctx.memoryProperties.memoryHeapCount; ++i)
        largestHeap = std::max(largestHeap, ctx.memoryProperties.memoryHeaps[i].size);
    GpuResources owner(ctx);
    try {
        createBuffer(owner, largestHeap + (VkDeviceSize(1) << 20), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                     VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        ADD_FAILURE() << "a buffer larger than every heap was created";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("more than its memory heap"), std::string::npos) << error.what();
    }
    // Nothing half-made is left: the validation layer reports a leaked buffer at teardown.
    EXPECT_EQ(owner.bytes(), 0u);
}

TEST_F(GpuResourcesTest, MoveAssignmentDestroysWhatWasOwnedBefore) {
    GpuResources owner(ctx);
    createHostBuffer(owner, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    GpuResources other(ctx);
    const Buffer kept = createHostBuffer(other, 512, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    const VkDeviceSize keptBytes = other.bytes();
    owner = std::move(other);
    EXPECT_EQ(owner.bytes(), keptBytes);
    EXPECT_EQ(kept.size, 512u);
}

} // namespace
} // namespace pf::test
