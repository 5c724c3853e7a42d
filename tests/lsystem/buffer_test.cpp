#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "lsystem/language/buffer.h"

namespace {

constexpr uintptr_t kHugePage = uintptr_t{2} << 20;

TEST(Buffer, LargeBuffersStartOnAHugePageBoundary) {
    lsys::Buffer<uint16_t> large(3'000'000);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(large.data()) % kHugePage, 0u);
    lsys::Buffer<float> small(1000);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(small.data()) % alignof(float), 0u);
}

// Growing across the huge-page threshold and shrinking back moves the
// contents between the two kinds of allocation; the sanitizer build checks
// that each is freed as it was allocated.
TEST(Buffer, ContentsSurviveGrowingAndShrinkingAcrossTheHugePageThreshold) {
    lsys::Buffer<uint32_t> buffer(1000);
    std::iota(buffer.begin(), buffer.end(), 0u);
    buffer.resize(1'500'000); // 6 MB: reallocated on a huge-page boundary
    EXPECT_EQ(reinterpret_cast<uintptr_t>(buffer.data()) % kHugePage, 0u);
    for (uint32_t i = 0; i < 1000; ++i) ASSERT_EQ(buffer[i], i);
    std::iota(buffer.begin(), buffer.end(), 0u);
    EXPECT_EQ(buffer.back(), 1'499'999u);
    buffer.resize(10);
    buffer.shrink_to_fit(); // back to an ordinary allocation
    for (uint32_t i = 0; i < 10; ++i) ASSERT_EQ(buffer[i], i);
}

} // namespace
