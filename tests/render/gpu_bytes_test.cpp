// FieldRenderer::gpuBytes against the device memory the process actually
// allocated while the renderer was built, counted outside the engine
// (device_memory.h).
#include "device_memory.h"
#include "gpu_test.h"

#include "engine/field/field_renderer.h"
#include "engine/scene/field_content.h"

#include <gtest/gtest.h>

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

} // namespace
} // namespace pf::test
