// The sun's texel grid (engine/field/shadow_map.h) and when the cache of
// static casters serves a frame (engine/field/shadow_cache.h): CPU only.
#include "engine/field/shadow_cache.h"
#include "shaders/shared/field_layouts.h"

#include <gtest/gtest.h>

#include "sun_fixture.h"

namespace pf {
namespace {

using test::kRadius;
using test::kSun;
using test::kTexels;
constexpr float kTexel = 2.0f * kRadius / float(kTexels);

ShadowView viewFrom(const glm::vec3& camera, const glm::vec3& focus) {
    ShadowView v;
    v.square = sunSquareAround(kSun, focus, kRadius, kTexels);
    v.sunDirection = kSun;
    v.camera = camera;
    v.pixelsPerMetre = 773.0f;
    return v;
}

// A point `texels` texels along the sun view's x axis from `p`.
glm::vec3 alongGrid(const SunSquare& square, const glm::vec3& p, float texels) {
    const glm::vec3 right(square.view[0][0], square.view[1][0], square.view[2][0]);
    return p + right * (texels * square.texel);
}

TEST(SunSquare, SnapsToWholeTexels) {
    const glm::vec3 focus(10.3f, 4.0f, -7.9f);
    const SunSquare a = sunSquareAround(kSun, focus, kRadius, kTexels);
    EXPECT_FLOAT_EQ(a.texel, kTexel);
    EXPECT_EQ(a.texels, kTexels);
    // Along the grid by whole texels: the origin moves by as many.
    const SunSquare b = sunSquareAround(kSun, alongGrid(a, focus, 37.0f), kRadius, kTexels);
    EXPECT_EQ(b.origin - a.origin, glm::ivec2(37, 0));
    // Along the sun: the same texels, another depth.
    const SunSquare c = sunSquareAround(kSun, focus - kSun * 20.0f, kRadius, kTexels);
    EXPECT_EQ(c.origin, a.origin);
    EXPECT_NEAR(c.depth - a.depth, 20.0f, 1e-3f);
}

TEST(SunSquare, ProjectionSpansTheSquareAndItsDepth) {
    const glm::vec3 focus(-30.0f, 2.0f, 45.0f);
    const SunSquare square = sunSquareAround(kSun, focus, kRadius, kTexels);
    const glm::mat4 viewProj = sunViewProjection(square, 250.0f);
    const glm::vec4 clip = viewProj * glm::vec4(focus, 1.0f);
    // The focus lies within a texel of the centre, halfway through the depth.
    EXPECT_LE(std::abs(clip.x), 2.0f / kTexels);
    EXPECT_LE(std::abs(clip.y), 2.0f / kTexels);
    EXPECT_NEAR(clip.z, 0.5f, 1e-4f);
    const glm::vec4 edge = viewProj * glm::vec4(alongGrid(square, focus, kTexels / 2 + 2.0f), 1.0f);
    EXPECT_GT(edge.x, 1.0f) << "a point past half the square lies outside it";
}

TEST(SunSquare, GrownSquareHoldsTheSquareOnTheSameGrid) {
    const SunSquare square = sunSquareAround(kSun, glm::vec3(5.0f), kRadius, kTexels);
    const SunSquare grown = grownSquare(square, 100);
    EXPECT_EQ(grown.texels, kTexels + 200);
    EXPECT_EQ(square.origin - grown.origin, glm::ivec2(100));
    EXPECT_TRUE(squareContains(grown, square));
    EXPECT_FALSE(squareContains(square, grown));
    SunSquare moved = square;
    moved.origin += glm::ivec2(100, -100);
    EXPECT_TRUE(squareContains(grown, moved)) << "at the corner of the margin";
    moved.origin.x += 1;
    EXPECT_FALSE(squareContains(grown, moved)) << "a texel past it";
}

TEST(ShadowCache, MarginIsTheReachInWholeTexels) {
    ShadowCacheSettings settings;
    EXPECT_EQ(shadowCacheMargin(settings, kTexel), 69u); // 8 / 0.1171875 = 68.3
    settings.reach = 16.0f;
    EXPECT_EQ(shadowCacheMargin(settings, kTexel), 137u);
}

TEST(ShadowCache, ServesSmallMovesAndNotFarOnes) {
    const ShadowCacheSettings settings;
    const glm::vec3 camera(0.0f, 20.0f, 0.0f), forward(0.6f, 0.0f, -0.8f);
    const ShadowView start = viewFrom(camera, camera + forward * 36.0f);
    const ShadowView cache = shadowCacheFor(start, shadowCacheMargin(settings, kTexel));
    EXPECT_TRUE(shadowCacheServes(cache, start, settings));
    for (float metres : {1.0f, 4.0f, 7.5f}) {
        const glm::vec3 moved = camera + forward * metres;
        EXPECT_TRUE(shadowCacheServes(cache, viewFrom(moved, moved + forward * 36.0f), settings)) << metres << " m";
    }
    const glm::vec3 far = camera + forward * 8.5f;
    EXPECT_FALSE(shadowCacheServes(cache, viewFrom(far, far + forward * 36.0f), settings)) << "past the reach";
    EXPECT_FALSE(shadowCacheServes(cache, viewFrom(camera, camera - forward * 36.0f), settings))
        << "turned round: the square ahead of the camera leaves the cache";
}

TEST(ShadowCache, DoesNotServeAnotherSunLodOrScale) {
    const ShadowCacheSettings settings;
    const ShadowView frame = viewFrom(glm::vec3(0.0f, 10.0f, 0.0f), glm::vec3(20.0f, 10.0f, 0.0f));
    const ShadowView cache = shadowCacheFor(frame, shadowCacheMargin(settings, kTexel));
    ShadowView other = frame;
    other.sunDirection = glm::normalize(kSun + glm::vec3(0.0f, 0.01f, 0.0f));
    EXPECT_FALSE(shadowCacheServes(cache, other, settings));
    other = frame;
    other.forcedLod = LOD_IMPOSTOR;
    EXPECT_FALSE(shadowCacheServes(cache, other, settings));
    other = frame;
    other.pixelsPerMetre *= 1.04f;
    EXPECT_TRUE(shadowCacheServes(cache, other, settings)) << "within the 5 % the cache allows";
    other.pixelsPerMetre = frame.pixelsPerMetre * 0.94f;
    EXPECT_FALSE(shadowCacheServes(cache, other, settings)) << "a wider field of view";
}

} // namespace
} // namespace pf
