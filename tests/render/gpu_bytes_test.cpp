// FieldRenderer::gpuBytes against the device memory the process actually
// allocated while the renderer was built, counted outside the engine
// (device_memory.h).
#include "device_memory.h"
#include "gpu_test.h"

#include "engine/field/field_renderer.h"
#include "engine/scene/field_content.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace pf::test {
namespace {

class GpuBytesTest : public GpuTest {};

// Every buffer and image of the renderer and of the passes it owns (cull,
// physics and pose, field motion, shadow map, impostor atlas) is counted,
// and all of it is freed with the renderer.
TEST_F(GpuBytesTest, GpuBytesIsTheDeviceMemoryTheRendererHolds) {
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_small.json");
    const VkDeviceSize before = liveDeviceMemoryBytes();
    {
        FieldRenderer renderer(ctx, buildFieldContent(scene), FieldRenderSettings{});
        ASSERT_GT(renderer.simulatedJoints(), 0u) << "the physics pass's buffers should not be empty";
        const VkDeviceSize held = liveDeviceMemoryBytes() - before;
        EXPECT_GT(held, 0u);
        EXPECT_EQ(renderer.gpuBytes(), held);
    }
    EXPECT_EQ(liveDeviceMemoryBytes(), before);
}

// The host side of the uploads (instance lists and staging copies) is
// checked against the memory budget before any device memory is allocated.
TEST_F(GpuBytesTest, UploadsPastTheMemoryBudgetAreRefusedBeforeAllocating) {
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_small.json");
    FieldContent content = buildFieldContent(scene);
    const uint64_t need = fieldUploadBytes(content);
    EXPECT_GE(need, content.plants.size() * 2 * sizeof(gpu::FieldInstance) +
                        content.models.vertices.size() * sizeof(gpu::FieldVertex));
    FieldRenderSettings settings;
    settings.memory = {need - 1};
    const VkDeviceSize before = liveDeviceMemoryBytes();
    try {
        FieldRenderer renderer(ctx, std::move(content), settings);
        FAIL() << "expected the uploads to be refused";
    } catch (const lsys::MemoryBudgetError& error) {
        EXPECT_NE(std::string(error.what()).find("GPU uploads needs"), std::string::npos) << error.what();
    }
    EXPECT_EQ(liveDeviceMemoryBytes(), before);
}

// A vertex pool larger than the device binds as one storage buffer is
// refused with its size, before any device memory is allocated (bound
// anyway, it is undefined behaviour the validation layer reports), as a
// DeviceLimitError, which the tools report as bad input (exit 2).
TEST_F(GpuBytesTest, AVertexPoolPastTheDevicesBufferRangeIsRefused) {
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_small.json");
    FieldContent content = buildFieldContent(scene);
    const uint64_t range = std::min<uint64_t>(ctx.properties.limits.maxStorageBufferRange,
                                              uint64_t(ctx.properties.limits.maxTexelBufferElements) * 16);
    content.models.vertices.resize(range / sizeof(gpu::FieldVertex) + 1);
    const VkDeviceSize before = liveDeviceMemoryBytes();
    try {
        FieldRenderer renderer(ctx, std::move(content), FieldRenderSettings{});
        FAIL() << "expected the vertex pool to be refused";
    } catch (const DeviceLimitError& error) {
        EXPECT_NE(std::string(error.what()).find("vertex pool (" + std::to_string(range / 64 + 1) + " vertices"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_EQ(liveDeviceMemoryBytes(), before);
}

} // namespace
} // namespace pf::test
