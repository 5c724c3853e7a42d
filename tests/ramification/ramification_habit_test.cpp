// What a tree type adds to its matrix: leaves and needles on the thin
// branches (Tankard 2001, §4.2.2.3), excurrent laterals, phyllotaxis, droop
// and several stems. None of them changes the branching the matrix draws.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "lsystem/ramification/ramification.h"
#include "lsystem/ramification/ramification_generate.h"
#include "ramification_test_support.h"

namespace lsys {
namespace {

RamificationTree fourOrders(uint64_t seed) {
    RamificationTree tree;
    tree.matrix.p = {{1.0}, {0.7, 0.3}, {0.4, 0.35, 0.25}, {0.3, 0.2, 0.2, 0.3}};
    tree.seed = seed;
    return tree;
}

using test::degreesBetween;
using test::headingOf;

size_t countOf(const PlantAsset& plant, PrimitiveKind kind, uint32_t material) {
    return std::count_if(plant.primitives.begin(), plant.primitives.end(),
                         [&](const Primitive& p) { return p.kind == kind && p.material == material; });
}

// Leaves are surfaces and needles two-sided segments: compiling the leafy
// tree counts what compiling the bare tree of the same seed counts.
TEST(RamificationHabit, FoliageHangsOnTheThinBranchesAndLeavesTheMatrixAlone) {
    for (const auto kind : {RamificationFoliage::Kind::Leaves, RamificationFoliage::Kind::Needles}) {
        RamificationTree leafy = fourOrders(9);
        leafy.foliage = {kind, 2, 3, 4, 0.1, 45.0, 0.02};
        const PlantAsset bare = plantOf(generateTree(fourOrders(9)));
        const GeneratedTree generated = generateTree(leafy);
        const PlantAsset plant = plantOf(generated);
        const CompiledRamification a = compileRamification(bare), b = compileRamification(plant);
        EXPECT_EQ(a.counts.a, b.counts.a);
        EXPECT_EQ(a.counts.b, b.counts.b);
        EXPECT_EQ(generated.branches, generateTree(fourOrders(9)).branches);
        // Branches of orders 1 and 2 are drawn in 3 pieces, each followed by a cluster of 4.
        uint64_t thin = 0;
        for (uint64_t count : {a.counts.a[0], a.counts.a[1]}) thin += count;
        const bool leaves = kind == RamificationFoliage::Kind::Leaves;
        EXPECT_EQ(countOf(plant, leaves ? PrimitiveKind::Surface : PrimitiveKind::Segment, leaves ? 1 : 5),
                  thin * 3 * 4);
        for (size_t i = 0; i < plant.joints.size(); ++i)
            if (b.jointOrder[i] == 0) EXPECT_FALSE(leaves) << "a leaf surface is no joint";
    }
}

// A side branch leaves its axis at least side_angle_min (70°, more than
// Tankard's θ_s = 50 (k − i) / (k − 1) of any order here); the axis goes on
// straight (main_angle 0) and equal children part at split_angle.
TEST(RamificationHabit, SideBranchesLeaveAtLeastTheMinimumAngle) {
    RamificationTree tree = fourOrders(3);
    tree.growth.minSideAngle = 70.0;
    tree.growth.mainAngle = 0.0;
    const PlantAsset plant = plantOf(generateTree(tree));
    const CompiledRamification compiled = compileRamification(plant);
    size_t sides = 0;
    for (const test::ChildAngle& child : test::childAngles(plant, compiled)) {
        const bool side = child.own != child.sibling && child.own != child.parentOrder;
        const double expected = child.own == child.sibling ? tree.growth.splitAngle : side ? 70.0 : 0.0;
        EXPECT_NEAR(child.degrees, expected, 0.01) << "joint " << child.joint;
        sides += side;
    }
    EXPECT_GT(sides, 5u);
}

// Droop bends side branches toward the ground and leaves the trunk as it
// grew, though it leans (main_angle turns it at every lateral).
TEST(RamificationHabit, DroopBendsSideBranchesNotTheTrunk) {
    RamificationTree straight = fourOrders(5);
    straight.matrix.p[3] = {0.4, 0.3, 0.25, 0.05}; // a trunk about 20 branches long
    RamificationTree drooping = straight;
    drooping.growth.droop = 0.2;
    const PlantAsset a = plantOf(generateTree(straight)), b = plantOf(generateTree(drooping));
    ASSERT_EQ(a.joints.size(), b.joints.size());
    const CompiledRamification orders = compileRamification(a);
    size_t lower = 0, side = 0, leaning = 0;
    for (size_t i = 0; i < a.joints.size(); ++i) {
        if (orders.jointOrder[i] == 4) { // the trunk: order 4 from the base up
            EXPECT_LT(glm::distance(headingOf(a.joints[i]), headingOf(b.joints[i])), 1e-5f) << "trunk joint " << i;
            leaning += headingOf(a.joints[i]).y < 0.9999f;
            continue;
        }
        ++side;
        lower += headingOf(b.joints[i]).y < headingOf(a.joints[i]).y - 1e-3f;
    }
    EXPECT_GT(leaning, 2u); // so gravity would bend the trunk too, were it drooping
    EXPECT_GT(side, 10u);
    EXPECT_GT(lower, side / 2);
}

// Several stems: each a whole tree of the matrix's orders, leaning out by
// stem_angle and rolled evenly about the base.
TEST(RamificationHabit, StemsAreWholeTreesFromOneBase) {
    RamificationTree tree = fourOrders(6);
    tree.growth.stems = 5;
    tree.growth.stemAngle = 30.0;
    const PlantAsset plant = plantOf(generateTree(tree));
    const CompiledRamification compiled = compileRamification(plant);
    ASSERT_EQ(compiled.counts.a.size(), 4u);
    std::vector<glm::vec3> bases;
    for (size_t i = 0; i < plant.joints.size(); ++i) {
        if (plant.joints[i].parent >= 0) continue;
        bases.push_back(headingOf(plant.joints[i]));
        EXPECT_EQ(compiled.jointOrder[i], 4u) << "stem " << bases.size();
    }
    ASSERT_EQ(bases.size(), 5u);
    for (size_t s = 0; s < bases.size(); ++s) {
        EXPECT_NEAR(degreesBetween(bases[s], glm::vec3(0, 1, 0)), 30.0, 0.01);
        const glm::vec3 next = bases[(s + 1) % bases.size()];
        const glm::vec2 a(bases[s].x, bases[s].z), b(next.x, next.z);
        EXPECT_NEAR(degreesBetween(glm::vec3(a, 0), glm::vec3(b, 0)), 72.0, 0.01);
    }
}

// Phyllotaxis rolls every branch point by the same angle: with neither twist
// nor turns of the axis, successive twigs of the trunk differ by it.
TEST(RamificationHabit, PhyllotaxisSpiralsTheLaterals) {
    RamificationTree tree;
    tree.matrix.p = {{1.0}, {0.9, 0.1}}; // the order-2 trunk bears twigs until it splits
    tree.seed = 2;
    tree.growth.mainAngle = 0.0;
    tree.growth.splitAngle = 10.0; // the final split's children are no twigs (50° from the trunk)
    tree.growth.phyllotaxis = 137.5;
    const PlantAsset plant = plantOf(generateTree(tree));
    std::vector<glm::vec3> twigs; // headings of the trunk's twigs, base up
    for (const Joint& joint : plant.joints)
        if (joint.parent >= 0 &&
            std::abs(degreesBetween(headingOf(plant.joints[joint.parent]), headingOf(joint)) - 50.0) < 0.01)
            twigs.push_back(headingOf(joint));
    ASSERT_GE(twigs.size(), 4u);
    for (size_t i = 1; i < twigs.size(); ++i) {
        const double turn =
            glm::degrees(std::atan2(twigs[i].z, twigs[i].x) - std::atan2(twigs[i - 1].z, twigs[i - 1].x));
        EXPECT_NEAR(std::abs(std::remainder(turn, 360.0)), 137.5, 0.05) << "twig " << i;
    }
}

} // namespace
} // namespace lsys
