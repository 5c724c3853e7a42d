// Trees generated from ramification matrices (Tankard 2001, §3.3, §4.2.2),
// and compiled back.
#include <gtest/gtest.h>

#include <cmath>

#include "lsystem/ramification/ramification.h"
#include "lsystem/ramification/ramification_generate.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "ramification_test_support.h"

namespace lsys {
namespace {

RamificationTree treeOf(std::vector<std::vector<double>> p, uint64_t seed = 1) {
    RamificationTree tree;
    tree.matrix.p = std::move(p);
    tree.seed = seed;
    return tree;
}

const std::vector<std::vector<double>> kFourOrders = {{1.0}, {0.7, 0.3}, {0.4, 0.35, 0.25}, {0.3, 0.2, 0.2, 0.3}};

TEST(RamificationGenerate, SameSeedSameTreeOtherSeedAnother) {
    const GeneratedTree a = generateTree(treeOf(kFourOrders, 5));
    const GeneratedTree b = generateTree(treeOf(kFourOrders, 5));
    const GeneratedTree c = generateTree(treeOf(kFourOrders, 6));
    EXPECT_EQ(toString(a.word, a.symbols), toString(b.word, b.symbols));
    EXPECT_NE(toString(a.word, a.symbols), toString(c.word, c.symbols));
    EXPECT_GT(a.branches, 1u);
}

TEST(RamificationGenerate, TheBranchBudgetStopsRunawayTrees) {
    RamificationTree tree = treeOf({}, 1);
    tree.matrix = balancedMatrix(6, 0.0); // p_kk = 0: only the guard ends the axes
    tree.maxBranches = 1000;
    EXPECT_THROW(generateTree(tree), RamificationBudgetError);
    EXPECT_EQ(generateTree(treeOf({})).branches, 0u);
}

// Balance 0 sets every p_kk to 0; the guard still ends every axis.
TEST(RamificationGenerate, AxesEndEvenWhereTheMatrixNeverSplits) {
    RamificationTree tree = treeOf({}, 3);
    tree.matrix = balancedMatrix(4, 0.0);
    const GeneratedTree generated = generateTree(tree);
    const CompiledRamification compiled = compileRamification(plantOf(generated).joints);
    EXPECT_EQ(compiled.counts.a.size(), 4u);
    EXPECT_EQ(compiled.jointOrder.size(), generated.branches);
}

// §3.3.3: length c1 k, width c2 L(k)^e; children of equal order at the split
// angle, of orders k and i < k at c_m i / (k − 1) and c_s (k − i) / (k − 1).
TEST(RamificationGenerate, LengthsWidthsAndAnglesFollowTheOrders) {
    RamificationTree tree = treeOf(kFourOrders, 11);
    const RamificationGrowth& growth = tree.growth;
    const PlantAsset plant = plantOf(generateTree(tree));
    const CompiledRamification compiled = compileRamification(plant.joints);
    for (size_t i = 0; i < plant.joints.size(); ++i) {
        const Joint& joint = plant.joints[i];
        const double length = growth.length * compiled.jointOrder[i];
        EXPECT_NEAR(joint.length, length, 1e-6);
        EXPECT_NEAR(2.0 * joint.startRadius, growth.width * std::pow(length, 4 / 2.0), 1e-6);
    }
    size_t checked = 0;
    for (const test::ChildAngle& child : test::childAngles(plant, compiled)) {
        const uint32_t k = child.parentOrder;
        double expected = growth.splitAngle;
        if (child.own != child.sibling)
            expected = child.own == k ? growth.mainAngle * child.sibling / (k - 1)
                                      : growth.sideAngle * (k - child.own) / (k - 1);
        EXPECT_NEAR(child.degrees, expected, 0.01) << "joint " << child.joint;
        ++checked;
    }
    EXPECT_GT(checked, 10u);
}

// A tree generated from a matrix, compiled again, gives the matrix back
// within sampling error: the counts of 300 trees pooled, each p_kj within
// 4 standard errors sqrt(p (1 − p) / a_k) of the guarded matrix's (a
// chance of about 6e-5 per entry for a correct generator).
TEST(RamificationGenerate, CompilingGeneratedTreesGivesTheMatrixBack) {
    const RamificationMatrix expected = guardedMatrix(treeOf(kFourOrders).matrix);
    RamificationCounts pooled;
    for (uint64_t seed = 1; seed <= 300; ++seed) {
        const CompiledRamification compiled =
            compileRamification(plantOf(generateTree(treeOf(kFourOrders, seed))).joints);
        ASSERT_EQ(compiled.counts.a.size(), 4u) << "seed " << seed; // the trunk has order 4
        if (pooled.a.empty())
            pooled = compiled.counts;
        else
            for (size_t k = 0; k < 4; ++k) {
                pooled.a[k] += compiled.counts.a[k];
                for (size_t j = 0; j <= k; ++j) pooled.b[k][j] += compiled.counts.b[k][j];
            }
    }
    const RamificationMatrix measured = ramificationMatrix(pooled);
    for (size_t k = 2; k <= 4; ++k) {
        for (size_t j = 1; j <= k; ++j) {
            const double p = expected.p[k - 1][j - 1];
            const double error = std::sqrt(p * (1.0 - p) / double(pooled.a[k - 1]));
            EXPECT_NEAR(measured.p[k - 1][j - 1], p, 4.0 * error) << "p_" << k << j << " over " << pooled.a[k - 1];
        }
    }
    EXPECT_GT(pooled.a[3], 300u);
}

// Twist (Tankard 2001, §3.3.1) is no part of the matrix: it rolls branches
// about their parents and leaves the branching as it was.
TEST(RamificationGenerate, TwistTurnsBranchesWithoutChangingTheBranching) {
    RamificationTree twisted = treeOf(kFourOrders, 4);
    twisted.growth.twist = 200.0;
    const GeneratedTree plain = generateTree(treeOf(kFourOrders, 4));
    const GeneratedTree turned = generateTree(twisted);
    EXPECT_NE(toString(plain.word, plain.symbols), toString(turned.word, turned.symbols));
    const PlantAsset a = plantOf(plain), b = plantOf(turned);
    ASSERT_EQ(a.joints.size(), b.joints.size());
    for (size_t i = 0; i < a.joints.size(); ++i) EXPECT_EQ(a.joints[i].parent, b.joints[i].parent);
    EXPECT_EQ(compileRamification(a.joints).jointOrder, compileRamification(b.joints).jointOrder);
    EXPECT_NE(a.bounds.max, b.bounds.max);
}

// The word is an L-system the parser reads back to the same plant.
TEST(RamificationGenerate, TheLsystemTextDrawsTheSameTree) {
    const GeneratedTree generated = generateTree(treeOf(kFourOrders, 2));
    ParseResult parsed = parseLsystem(lsystemText(generated, "a test\nof two lines"));
    ASSERT_TRUE(parsed.ok());
    const PlantAsset reread = plantFromGrammar(parsed.grammar, derive(parsed.grammar));
    const PlantAsset direct = plantOf(generated);
    ASSERT_EQ(reread.joints.size(), direct.joints.size());
    for (size_t i = 0; i < direct.joints.size(); ++i) EXPECT_EQ(reread.joints[i].parent, direct.joints[i].parent);
}

} // namespace
} // namespace lsys
