#include "gpu_test.h"

namespace pf::test {

void GpuTest::SetUp() {
    GpuOptions options;
    options.validation = true;
    ASSERT_NO_THROW(createHeadlessContext(ctx, options));
}

void GpuTest::TearDown() {
    resources.destroy();
    // Destroying first lets the layer report leaked objects as well.
    destroyContext(ctx);
    if (!ctx.validationLog) return;
    const std::vector<std::string> messages = ctx.validationLog->snapshot();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), first: " << messages.front();
}

} // namespace pf::test
