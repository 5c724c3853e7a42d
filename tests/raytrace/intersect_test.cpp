// The exact ray tests against analytic answers: rays along and across a
// frustum's axis, tangent rays, misses, rays from inside, tMax cut-offs.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "lsystem/raytrace/intersect.h"

namespace lsys {
namespace {

constexpr float kTolerance = 1e-5f;

Ray rayFrom(glm::vec3 origin, glm::vec3 direction) { return Ray{origin, direction}; }

void expectHit(const std::optional<ShapeHit>& hit, float t, glm::vec3 normal) {
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, t, kTolerance);
    EXPECT_NEAR(glm::distance(hit->normal, glm::normalize(normal)), 0.0f, kTolerance)
        << hit->normal.x << " " << hit->normal.y << " " << hit->normal.z;
}

TEST(IntersectFrustum, AlongTheAxisHitsTheBaseCap) {
    expectHit(intersectFrustum(rayFrom({0, -1, 0}, {0, 1, 0}), 2.0f, 0.5f, 0.25f), 1.0f, {0, -1, 0});
}

TEST(IntersectFrustum, AlongTheAxisFromAboveHitsTheTipCap) {
    expectHit(intersectFrustum(rayFrom({0, 5, 0}, {0, -1, 0}), 2.0f, 0.5f, 0.25f), 3.0f, {0, 1, 0});
}

TEST(IntersectFrustum, AcrossACylinder) {
    expectHit(intersectFrustum(rayFrom({-2, 1, 0}, {1, 0, 0}), 2.0f, 0.5f, 0.5f), 1.5f, {-1, 0, 0});
}

// A cone from radius 1 at y = 0 to 0 at y = 1 is 0.5 wide halfway; its side
// leans in at 45°, so the outward normal there is (−1, 1, 0)/√2.
TEST(IntersectFrustum, AcrossAConeTheNormalLeansTowardsTheTip) {
    expectHit(intersectFrustum(rayFrom({-3, 0.5f, 0}, {1, 0, 0}), 1.0f, 1.0f, 0.0f), 2.5f, {-1, 1, 0});
}

TEST(IntersectFrustum, AWideningFrustumLeansTheOtherWay) {
    expectHit(intersectFrustum(rayFrom({-3, 0.5f, 0}, {1, 0, 0}), 1.0f, 0.0f, 1.0f), 2.5f, {-1, -1, 0});
}

TEST(IntersectFrustum, TheDirectionsLengthScalesT) {
    expectHit(intersectFrustum(rayFrom({-2, 1, 0}, {4, 0, 0}), 2.0f, 0.5f, 0.5f), 0.375f, {-1, 0, 0});
}

TEST(IntersectFrustum, TangentRayTouchesTheSide) {
    expectHit(intersectFrustum(rayFrom({-2, 1, 0.5f}, {1, 0, 0}), 2.0f, 0.5f, 0.5f), 2.0f, {0, 0, 1});
    EXPECT_FALSE(intersectFrustum(rayFrom({-2, 1, 0.5001f}, {1, 0, 0}), 2.0f, 0.5f, 0.5f));
}

TEST(IntersectFrustum, MissesPastTheEndsAndBeside) {
    EXPECT_FALSE(intersectFrustum(rayFrom({-2, 2.01f, 0}, {1, 0, 0}), 2.0f, 0.5f, 0.5f));
    EXPECT_FALSE(intersectFrustum(rayFrom({-2, -0.01f, 0}, {1, 0, 0}), 2.0f, 0.5f, 0.5f));
    EXPECT_FALSE(intersectFrustum(rayFrom({0.6f, -1, 0}, {0, 1, 0}), 2.0f, 0.5f, 0.5f));
    // Beside the narrow end of a cone, inside the wide end's radius.
    EXPECT_FALSE(intersectFrustum(rayFrom({-2, 0.9f, 0.2f}, {1, 0, 0}), 1.0f, 1.0f, 0.0f));
    // Pointing away.
    EXPECT_FALSE(intersectFrustum(rayFrom({-2, 1, 0}, {-1, 0, 0}), 2.0f, 0.5f, 0.5f));
}

TEST(IntersectFrustum, FromInsideHitsTheWallAndTheCaps) {
    expectHit(intersectFrustum(rayFrom({0, 1, 0}, {1, 0, 0}), 2.0f, 0.5f, 0.5f), 0.5f, {1, 0, 0});
    expectHit(intersectFrustum(rayFrom({0, 0.5f, 0}, {0, 1, 0}), 2.0f, 0.5f, 0.5f), 1.5f, {0, 1, 0});
    expectHit(intersectFrustum(rayFrom({0, 0.5f, 0}, {0, -1, 0}), 2.0f, 0.5f, 0.5f), 0.5f, {0, -1, 0});
}

TEST(IntersectFrustum, ObliqueRayThroughTheCapAndOutTheSide) {
    // Enters the base disc at (0, 0, 0) and leaves the side of the cylinder
    // of radius 0.5 at x = 0.5, y = 0.5.
    Ray ray = rayFrom({-1, -1, 0}, {1, 1, 0});
    expectHit(intersectFrustum(ray, 2.0f, 0.5f, 0.5f), 1.0f, {0, -1, 0});
    ray.tMin = 1.0001f;
    expectHit(intersectFrustum(ray, 2.0f, 0.5f, 0.5f), 1.5f, {1, 0, 0});
}

TEST(IntersectFrustum, HitsOutsideTMinTMaxAreNotHits) {
    Ray ray = rayFrom({-2, 1, 0}, {1, 0, 0});
    ray.tMax = 1.4f;
    EXPECT_FALSE(intersectFrustum(ray, 2.0f, 0.5f, 0.5f));
    ray.tMax = 10.0f;
    ray.tMin = 1.6f; // past the near wall: the far wall
    expectHit(intersectFrustum(ray, 2.0f, 0.5f, 0.5f), 2.5f, {1, 0, 0});
}

TEST(IntersectFrustum, APointedConeHasNoTipCap) {
    // Straight down the axis onto the apex: the side at y = 1, radius 0.
    const std::optional<ShapeHit> hit = intersectFrustum(rayFrom({0, 3, 0}, {0, -1, 0}), 1.0f, 1.0f, 0.0f);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 2.0f, 1e-3f);
    EXPECT_FALSE(intersectFrustum(rayFrom({0.001f, 3, 0.001f}, {0, -1, 0}), 1.0f, 0.0f, 0.0f));
}

TEST(IntersectSphere, FromOutsideInsideAndTangent) {
    expectHit(intersectSphere(rayFrom({0, 0, -5}, {0, 0, 1}), 1.0f), 4.0f, {0, 0, -1});
    expectHit(intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), 1.0f), 1.0f, {0, 0, 1});
    expectHit(intersectSphere(rayFrom({0, 0, -5}, {0, 0, 2}), 1.0f), 2.0f, {0, 0, -1});
    expectHit(intersectSphere(rayFrom({1, 0, -5}, {0, 0, 1}), 1.0f), 5.0f, {1, 0, 0});
    EXPECT_FALSE(intersectSphere(rayFrom({1.001f, 0, -5}, {0, 0, 1}), 1.0f));
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, -5}, {0, 0, -1}), 1.0f));
}

TEST(IntersectTriangle, BothSidesKeepTheWindingNormal) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    expectHit(intersectTriangle(rayFrom({0.25f, 0.25f, 1}, {0, 0, -1}), a, b, c), 1.0f, {0, 0, 1});
    expectHit(intersectTriangle(rayFrom({0.25f, 0.25f, -2}, {0, 0, 1}), a, b, c), 2.0f, {0, 0, 1});
    expectHit(intersectTriangle(rayFrom({0.25f, 0.25f, -2}, {0, 0, 1}), a, c, b), 2.0f, {0, 0, -1});
}

TEST(IntersectTriangle, MissesOutsideParallelAndBehind) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_FALSE(intersectTriangle(rayFrom({0.6f, 0.6f, 1}, {0, 0, -1}), a, b, c));
    EXPECT_FALSE(intersectTriangle(rayFrom({-0.1f, 0.5f, 1}, {0, 0, -1}), a, b, c));
    EXPECT_FALSE(intersectTriangle(rayFrom({0.25f, 0.25f, 1}, {1, 0, 0}), a, b, c));
    EXPECT_FALSE(intersectTriangle(rayFrom({0.25f, 0.25f, 1}, {0, 0, 1}), a, b, c));
    EXPECT_FALSE(intersectTriangle(rayFrom({0.25f, 0.25f, 1}, {0, 0, -1}), a, b, a)); // degenerate
}

TEST(Intersect, ARayWithoutADirectionOrWithNaNsHitsNothing) {
    const float nan = std::nanf("");
    EXPECT_FALSE(intersectFrustum(rayFrom({-2, 1, 0}, {0, 0, 0}), 2.0f, 0.5f, 0.5f));
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, 0}, {0, 0, 0}), 1.0f));
    EXPECT_FALSE(intersectFrustum(rayFrom({nan, 1, 0}, {1, 0, 0}), 2.0f, 0.5f, 0.5f));
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, -5}, {0, nan, 1}), 1.0f));
    EXPECT_FALSE(intersectTriangle(rayFrom({0.25f, 0.25f, nan}, {0, 0, -1}), {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
}

TEST(BoxEntry, EntersAtTheNearFaceOrAtTMinInside) {
    const Bounds box{glm::vec3(-1), glm::vec3(1)};
    EXPECT_FLOAT_EQ(*boxEntry(rayFrom({-3, 0, 0}, {1, 0, 0}), box), 2.0f);
    EXPECT_FLOAT_EQ(*boxEntry(rayFrom({0, 0, 0}, {1, 0, 0}), box), 0.0f);
    EXPECT_FALSE(boxEntry(rayFrom({-3, 1.5f, 0}, {1, 0, 0}), box));
    EXPECT_FALSE(boxEntry(rayFrom({-3, 0, 0}, {-1, 0, 0}), box));
    Ray shortRay = rayFrom({-3, 0, 0}, {1, 0, 0});
    shortRay.tMax = 1.5f;
    EXPECT_FALSE(boxEntry(shortRay, box));
    EXPECT_FALSE(boxEntry(rayFrom({-3, 0, 0}, {1, 0, 0}), Bounds{}));
}

TEST(BoxEntry, ARayAlongAFaceEntersAndOneJustOutsideItDoesNot) {
    // Parallel to y and z: the slab test meets 0 · ∞ on the faces y = ±1 and z = 1.
    const Bounds box{glm::vec3(-1), glm::vec3(1)};
    EXPECT_FLOAT_EQ(*boxEntry(rayFrom({-3, 1, 0}, {1, 0, 0}), box), 2.0f);
    EXPECT_FLOAT_EQ(*boxEntry(rayFrom({-3, -1, 1}, {1, 0, 0}), box), 2.0f);
    EXPECT_FALSE(boxEntry(rayFrom({-3, std::nextafter(1.0f, 2.0f), 0}, {1, 0, 0}), box));
    EXPECT_FALSE(boxEntry(rayFrom({-3, 0, std::nextafter(-1.0f, -2.0f)}, {1, 0, 0}), box));
}

} // namespace
} // namespace lsys
