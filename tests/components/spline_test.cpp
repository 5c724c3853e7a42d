// Tankard 2001, §4.1.1.4: the patch lookup as NOTES.md corrects it, Hermite
// patches through the control points, and attributes read from splines.
#include "lsystem/components/spline.h"

#include <gtest/gtest.h>

namespace lsys::components {
namespace {

Spline line(std::vector<glm::vec3> positions) {
    Spline spline;
    for (const glm::vec3& p : positions) spline.points.push_back({p, {}});
    setCatmullRomTangents(spline.points);
    return spline;
}

TEST(SplinePatch, UIsSplitIntoPatchAndLocalDistance) {
    // c = 5 control points, 4 patches: n = ⌊4u⌋, l = 4u − n.
    const PatchPosition middle = patchAt(5, 0.6f);
    EXPECT_EQ(middle.patch, 2u);
    EXPECT_NEAR(middle.local, 0.4f, 1e-5f);
}

TEST(SplinePatch, PatchBoundariesStartTheNextPatch) {
    for (size_t i = 0; i < 4; ++i) {
        const PatchPosition at = patchAt(5, float(i) / 4.0f);
        EXPECT_EQ(at.patch, i);
        EXPECT_NEAR(at.local, 0.0f, 1e-6f);
    }
}

TEST(SplinePatch, UOfOneIsTheEndOfTheLastPatchNotPastIt) {
    // ⌊u(c−1)⌋ alone would give patch c−1, which has no end point.
    const PatchPosition end = patchAt(5, 1.0f);
    EXPECT_EQ(end.patch, 3u);
    EXPECT_FLOAT_EQ(end.local, 1.0f);
    EXPECT_EQ(patchAt(5, 2.0f).patch, 3u); // clamped
    EXPECT_EQ(patchAt(5, -1.0f).patch, 0u);
}

TEST(SplinePosition, PassesThroughEveryControlPointIncludingTheLast) {
    const Spline spline = line({{0, 0, 0}, {1, 2, 0}, {0, 3, 1}, {-1, 5, 0}});
    for (size_t i = 0; i < spline.points.size(); ++i) {
        const glm::vec3 p = splinePosition(spline, float(i) / 3.0f);
        EXPECT_NEAR(p.x, spline.points[i].position.x, 1e-5f) << i;
        EXPECT_NEAR(p.y, spline.points[i].position.y, 1e-5f) << i;
        EXPECT_NEAR(p.z, spline.points[i].position.z, 1e-5f) << i;
    }
}

TEST(SplinePosition, HermitePatchFollowsItsTangents) {
    // One patch from 0 to 1 with tangents 0 at both ends: smoothstep.
    Spline spline{{{{0, 0, 0}, {0, 0, 0}}, {{1, 0, 0}, {0, 0, 0}}}};
    EXPECT_NEAR(splinePosition(spline, 0.25f).x, 3 * 0.0625f - 2 * 0.015625f, 1e-6f);
    EXPECT_NEAR(splineTangent(spline, 0.5f).x, 1.5f, 1e-6f);
    EXPECT_NEAR(splineTangent(spline, 0.0f).x, 0.0f, 1e-6f);
}

TEST(SplinePosition, CatmullRomTangentsMakeAStraightLineUniform) {
    const Spline spline = line({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}});
    EXPECT_NEAR(splinePosition(spline, 0.3f).y, 0.6f, 1e-5f);
    EXPECT_NEAR(splineTangent(spline, 0.7f).y, 1.0f, 1e-5f); // per patch: one unit of y
}

TEST(Attribute, SingleValuedIsTheSameEverywhere) {
    const Attribute radius = constant(0.3f);
    EXPECT_EQ(valueAt(radius, 0.0f), 0.3f);
    EXPECT_EQ(valueAt(radius, 1.0f), 0.3f);
}

TEST(Attribute, SplineValuedIsReadFromTheCurvesX) {
    Attribute scale;
    scale.spline = line({{1.0f, 0, 0}, {0.5f, 0.5f, 0}, {0.2f, 1, 0}});
    EXPECT_NEAR(valueAt(scale, 0.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(valueAt(scale, 0.5f), 0.5f, 1e-6f);
    EXPECT_NEAR(valueAt(scale, 1.0f), 0.2f, 1e-6f);
    const float between = valueAt(scale, 0.75f);
    EXPECT_LT(between, 0.5f);
    EXPECT_GT(between, 0.2f);
}

} // namespace
} // namespace lsys::components
