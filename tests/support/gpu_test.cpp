#include "gpu_test.h"

namespace pf::test {

void createValidatedContext(GpuContext& ctx) {
    GpuOptions options;
    options.validation = true;
    ASSERT_NO_THROW(createHeadlessContext(ctx, options));
}

void destroyValidatedContext(GpuContext& ctx) {
    // Destroying first lets the layer report leaked objects as well.
    destroyContext(ctx);
    if (!ctx.validationLog) return;
    const std::vector<std::string> messages = ctx.validationLog->snapshot();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), first: " << messages.front();
}

void GpuTest::SetUp() { createValidatedContext(ctx); }

void GpuTest::TearDown() {
    resources.destroy();
    destroyValidatedContext(ctx);
}

} // namespace pf::test
