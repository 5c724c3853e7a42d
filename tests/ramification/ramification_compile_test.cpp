// Compiling plants into ramification matrices (Tankard 2001, §2.2).
#include <gtest/gtest.h>

#include "lsystem/ramification/ramification.h"
#include "ramification_test_support.h"

namespace lsys {
namespace {

using test::plantOfFile;
using test::plantOfWord;

// Tankard's Figure 3 (lost) rebuilt as tests/ramification/data/figure3.lsys,
// whose comment derives every order by hand.
TEST(RamificationCompile, FigureThreeGivesTankardsMatrix) {
    const CompiledRamification compiled = compileRamification(plantOfFile(test::testDataPath("figure3.lsys")).joints);
    // Joints in drawing order: T, twig, T2, A, twig, A', twig, twig, B, twig, B', twig, B'', twig, twig.
    EXPECT_EQ(compiled.jointOrder, (std::vector<uint32_t>{3, 1, 3, 2, 1, 2, 1, 1, 2, 1, 2, 1, 2, 1, 1}));
    EXPECT_EQ(compiled.counts.a, (std::vector<uint64_t>{8, 5, 2}));
    EXPECT_EQ(compiled.counts.b[1], (std::vector<uint64_t>{3, 2}));
    EXPECT_EQ(compiled.counts.b[2], (std::vector<uint64_t>{1, 0, 1}));
    const RamificationMatrix matrix = ramificationMatrix(compiled.counts);
    ASSERT_EQ(matrix.orders(), 3u);
    EXPECT_EQ(matrix.p[0], (std::vector<double>{1.0}));
    EXPECT_DOUBLE_EQ(matrix.p[1][0], 3.0 / 5.0);
    EXPECT_DOUBLE_EQ(matrix.p[1][1], 2.0 / 5.0);
    EXPECT_EQ(matrix.p[2], (std::vector<double>{0.5, 0.0, 0.5}));
}

// Segments drawn without branching are one branch, whatever their number.
TEST(RamificationCompile, ChainsOfSegmentsAreOneBranch) {
    const CompiledRamification compiled = compileRamification(plantOfWord("FFF[+FF]F").joints);
    EXPECT_EQ(compiled.jointOrder, (std::vector<uint32_t>{2, 2, 2, 1, 1, 1}));
    EXPECT_EQ(compiled.counts.a, (std::vector<uint64_t>{2, 1}));
    EXPECT_EQ(compiled.counts.b[1], (std::vector<uint64_t>{0, 1}));
}

// A branch point of n children is n - 1 binary ones, children by decreasing
// order; the n - 2 zero-length branches between them are counted.
TEST(RamificationCompile, BranchPointsOfMoreChildrenAreBinaryJoinsInARow) {
    // Three twigs: (1, 1) -> a zero-length order 2, then (2, 1) -> the real order 2.
    CompiledRamification compiled = compileRamification(plantOfWord("F[+F][-F]F").joints);
    EXPECT_EQ(compiled.jointOrder[0], 2u);
    EXPECT_EQ(compiled.counts.a, (std::vector<uint64_t>{3, 2}));
    EXPECT_EQ(compiled.counts.b[1], (std::vector<uint64_t>{1, 1}));
    // Children of orders 2, 2 and 1: (2, 2) -> 3, then (3, 1) -> 3: the generalised Strahler order.
    compiled = compileRamification(plantOfWord("F[+F[+F]F][-F]F[+F]F").joints);
    EXPECT_EQ(compiled.jointOrder[0], 3u);
    EXPECT_EQ(compiled.counts.a, (std::vector<uint64_t>{5, 2, 2}));
    EXPECT_EQ(compiled.counts.b[2], (std::vector<uint64_t>{1, 0, 1}));
    // Four twigs: three joins, two of them zero-length.
    compiled = compileRamification(plantOfWord("F[+F][-F][&F]F").joints);
    EXPECT_EQ(compiled.counts.a, (std::vector<uint64_t>{4, 3}));
    EXPECT_EQ(compiled.counts.b[1], (std::vector<uint64_t>{2, 1}));
}

// Needles (segments of the two-sided material 5) are leaves, not branches: a
// plant's matrix is its woody skeleton's; a branch growing on a needle hangs
// from the branch below it.
TEST(RamificationCompile, FoliageSegmentsAreNoBranches) {
    const CompiledRamification needles = compileRamification(plantOfWord("F[;(5)F]F[+F][;(5)-F]F"));
    EXPECT_EQ(needles.jointOrder, (std::vector<uint32_t>{2, 0, 2, 1, 0, 1}));
    EXPECT_EQ(needles.counts.a, compileRamification(plantOfWord("FF[+F]F")).counts.a);
    const CompiledRamification onNeedle = compileRamification(plantOfWord("F;(5)F;(0)F[+F]F"));
    EXPECT_EQ(onNeedle.jointOrder,
              (std::vector<uint32_t>{2, 0, 2, 1, 1})); // the F after the needle goes on from the first
    EXPECT_EQ(onNeedle.counts.a, (std::vector<uint64_t>{2, 1}));
    // The same words as bare joints: every segment is a branch.
    EXPECT_EQ(compileRamification(plantOfWord("F[;(5)F]F[+F][;(5)-F]F").joints).counts.a,
              (std::vector<uint64_t>{4, 3}));
}

TEST(RamificationCompile, SeparateRootsAreSeparateTreesAndNoJointsNoMatrix) {
    const CompiledRamification roots = compileRamification(plantOfWord("[F][-F[+F]F]").joints);
    EXPECT_EQ(roots.counts.a, (std::vector<uint64_t>{3, 1}));
    const CompiledRamification empty = compileRamification(plantOfWord("f+f").joints);
    EXPECT_TRUE(empty.counts.a.empty());
    EXPECT_EQ(ramificationMatrix(empty.counts).orders(), 0u);
}

// The ABOP trees of data/: every row sums to 1; a plant of binary branch
// points has one more tip than branch points per tree.
TEST(RamificationCompile, AbopTreesGiveRowsSummingToOne) {
    for (const char* plant : {"plants/monopodial_tree.lsys", "plants/sympodial_tree.lsys", "plants/conifer.lsys",
                              "plants/abop/fig2_6a_monopodial_tree", "plants/abop/fig2_7a_sympodial_tree",
                              "plants/abop/fig2_8a_ternary_tree", "plants/abop/fig1_24d_bracketed_plant"}) {
        SCOPED_TRACE(plant);
        const PlantAsset asset = plantOfFile(test::dataPath(plant));
        const CompiledRamification compiled = compileRamification(asset.joints);
        const RamificationMatrix matrix = ramificationMatrix(compiled.counts);
        ASSERT_GE(matrix.orders(), 2u);
        for (size_t k = 1; k <= matrix.orders(); ++k) {
            ASSERT_EQ(matrix.p[k - 1].size(), k);
            double sum = 0.0;
            for (double value : matrix.p[k - 1]) sum += value;
            EXPECT_NEAR(sum, 1.0, 1e-12) << "row " << k;
            EXPECT_GT(compiled.counts.a[k - 1], 0u) << "order " << k;
        }
        // Each branch of order k >= 2 has two children: branches = 2 x (non-tips) + roots.
        uint64_t branches = 0, splits = 0;
        for (size_t k = 1; k <= matrix.orders(); ++k) {
            branches += compiled.counts.a[k - 1];
            if (k >= 2) splits += compiled.counts.a[k - 1];
        }
        uint64_t roots = 0;
        for (const Joint& joint : asset.joints) roots += joint.parent < 0;
        EXPECT_EQ(branches, 2 * splits + roots);
    }
}

} // namespace
} // namespace lsys
