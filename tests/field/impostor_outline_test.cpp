// The outlines billboards are drawn as (engine/field/impostor_outline.h): every
// texel the alpha test can keep lies inside, empty frames draw nothing, and
// the rectangle is much smaller than the frame for plant-like shapes.
#include "engine/field/impostor_outline.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace {

using pf::ImpostorOutline;

struct Coverage {
    uint32_t size;
    std::vector<uint8_t> alpha;
    uint8_t& at(uint32_t x, uint32_t y) { return alpha[size_t(y) * size + x]; }
};

Coverage empty(uint32_t size) { return {size, std::vector<uint8_t>(size_t(size) * size, 0)}; }

// Twice the signed area of (a, b, p): which side of a→b the point p is on.
float side(glm::vec2 a, glm::vec2 b, glm::vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// p inside the convex outline (or on its edge), whichever way round it goes.
bool inside(const ImpostorOutline& o, glm::vec2 p) {
    bool anyPositive = false, anyNegative = false;
    for (size_t i = 0; i < o.size(); ++i) {
        const glm::vec2 a = o[i], b = o[(i + 1) % o.size()];
        if (a == b) continue;
        const float s = side(a, b, p);
        anyPositive |= s > 1e-5f;
        anyNegative |= s < -1e-5f;
    }
    return !(anyPositive && anyNegative);
}

// Every covered texel, grown by the margin and clipped to the frame, inside.
void expectContainsCoverage(const ImpostorOutline& o, const Coverage& c, float margin) {
    for (uint32_t y = 0; y < c.size; ++y) {
        for (uint32_t x = 0; x < c.size; ++x) {
            if (c.alpha[size_t(y) * c.size + x] == 0) continue;
            const glm::vec2 lo = glm::max(glm::vec2(x, y) - margin, glm::vec2(0.0f));
            const glm::vec2 hi = glm::min(glm::vec2(x + 1, y + 1) + margin, glm::vec2(float(c.size)));
            for (glm::vec2 corner : {lo, hi, glm::vec2(lo.x, hi.y), glm::vec2(hi.x, lo.y)})
                ASSERT_TRUE(inside(o, corner / float(c.size))) << "texel " << x << ", " << y;
        }
    }
}

// The corners go one way round (convex, not self-intersecting).
void expectConvex(const ImpostorOutline& o) {
    bool anyPositive = false, anyNegative = false;
    for (size_t i = 0; i < o.size(); ++i) {
        const glm::vec2 a = o[i], b = o[(i + 1) % o.size()], c = o[(i + 2) % o.size()];
        const float s = side(a, b, c);
        anyPositive |= s > 1e-6f;
        anyNegative |= s < -1e-6f;
    }
    EXPECT_FALSE(anyPositive && anyNegative);
}

TEST(ImpostorOutline, EmptyFrameDrawsNothing) {
    const Coverage c = empty(32);
    const ImpostorOutline o = pf::impostorOutline(c.alpha, c.size, 2.0f);
    EXPECT_EQ(pf::outlineArea(o), 0.0f);
}

TEST(ImpostorOutline, FullFrameIsTheWholeFrame) {
    Coverage c = empty(16);
    for (uint8_t& a : c.alpha) a = 255;
    const ImpostorOutline o = pf::impostorOutline(c.alpha, c.size, 2.0f);
    EXPECT_NEAR(pf::outlineArea(o), 1.0f, 1e-6f);
    for (glm::vec2 p : o) EXPECT_TRUE(p.x >= 0.0f && p.x <= 1.0f && p.y >= 0.0f && p.y <= 1.0f);
}

// A conifer's frame: a narrow cone on a thin trunk, centred, in a frame as
// wide as the plant's widest view: the rectangle is the cone's width, grown
// by the margin.
TEST(ImpostorOutline, ConeIsBoxedTightlyInsideTheFrame) {
    Coverage c = empty(32);
    for (uint32_t y = 2; y < 26; ++y)
        for (uint32_t x = 0; x < 32; ++x)
            if (std::abs(float(x) + 0.5f - 16.0f) < 0.12f * float(y)) c.at(x, y) = 200;
    for (uint32_t y = 26; y < 32; ++y) c.at(15, y) = c.at(16, y) = 255;
    const ImpostorOutline o = pf::impostorOutline(c.alpha, c.size, 1.0f);
    expectContainsCoverage(o, c, 1.0f);
    expectConvex(o);
    EXPECT_EQ(o[0], glm::vec2(12.0f, 4.0f) / 32.0f); // the first covered row is 5
    EXPECT_EQ(o[2], glm::vec2(20.0f, 32.0f) / 32.0f);
    EXPECT_LT(pf::outlineArea(o), 0.3f);
    for (glm::vec2 p : o) EXPECT_TRUE(p.x >= 0.0f && p.x <= 1.0f && p.y >= 0.0f && p.y <= 1.0f);
}

TEST(ImpostorOutline, ACornerTexelGrownByTheMarginIsClippedToTheFrame) {
    Coverage c = empty(8);
    c.at(7, 0) = 1; // the faintest coverage counts
    const ImpostorOutline o = pf::impostorOutline(c.alpha, c.size, 2.0f);
    expectContainsCoverage(o, c, 2.0f);
    EXPECT_NEAR(pf::outlineArea(o), (3.0f / 8.0f) * (3.0f / 8.0f), 1e-6f);
}

TEST(ImpostorOutline, RandomBlobsAreAlwaysContained) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 200; ++trial) {
        Coverage c = empty(24);
        const int blobs = 1 + int(random() % 4);
        for (int b = 0; b < blobs; ++b) {
            const float cx = float(random() % 24), cy = float(random() % 24), r = 1.0f + float(random() % 6);
            for (uint32_t y = 0; y < c.size; ++y)
                for (uint32_t x = 0; x < c.size; ++x)
                    if (glm::length(glm::vec2(x, y) - glm::vec2(cx, cy)) < r) c.at(x, y) = uint8_t(1 + random() % 255);
        }
        const float margin = float(trial % 3);
        const ImpostorOutline o = pf::impostorOutline(c.alpha, c.size, margin);
        expectContainsCoverage(o, c, margin);
        expectConvex(o);
    }
}

TEST(ImpostorOutline, WrongSizeIsAnError) {
    const std::vector<uint8_t> alpha(10, 0);
    EXPECT_THROW(pf::impostorOutline(alpha, 4, 1.0f), std::runtime_error);
}

} // namespace
