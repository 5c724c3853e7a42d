// A test fixture with a headless Vulkan context on which the Khronos
// validation layer is always on: any validation message fails the test.
#pragma once

#include "engine/vk/gpu_resources.h"

#include <gtest/gtest.h>

namespace pf::test {

// A headless context with the validation layer on (a test's own, where the
// fixture's one context is not enough).
void createValidatedContext(GpuContext& ctx);
// Destroys the context, then fails the test if the layer said anything.
void destroyValidatedContext(GpuContext& ctx);

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    GpuContext ctx;
    // Owns what a test creates; destroyed before the context.
    GpuResources resources{ctx};
};

} // namespace pf::test
