// Every dialect file in data/plants/dialects derives exactly as its native twin,
// and the module counts of the source documents' worked examples (computed
// independently of this project) come out of the dialect files themselves.

#include <algorithm>

#include "dialect_test_support.h"

namespace lsys::test {
namespace {

struct Twin {
    const char* dialectFile;
    const char* nativeFile;
    int steps;
    uint64_t seed;
};

class DialectTwins : public ::testing::TestWithParam<Twin> {};

TEST_P(DialectTwins, DeriveTheSameString) {
    const Twin& twin = GetParam();
    Grammar dialect = loadOk(twin.dialectFile);
    Grammar native = loadOk(twin.nativeFile);
    EXPECT_EQ(dialect.derivationLength, native.derivationLength);
    std::string expected = toString(deriveSteps(native, twin.steps, twin.seed), native.symbols);
    std::string actual = toString(deriveSteps(dialect, twin.steps, twin.seed), dialect.symbols);
    EXPECT_GT(expected.size(), 0u);
    size_t differ =
        std::mismatch(actual.begin(), actual.end(), expected.begin(), expected.end()).first - actual.begin();
    EXPECT_EQ(actual, expected) << "first difference at " << differ << ": '" << actual.substr(differ, 60)
                                << "' instead of '" << expected.substr(differ, 60) << "'";
}

INSTANTIATE_TEST_SUITE_P(
    Data, DialectTwins,
    ::testing::Values(Twin{"plants/dialects/koch_curve.crankshaw", "plants/koch_curve.lsys", 4, 0},
                      Twin{"plants/dialects/fractal_bush.crankshaw", "plants/fractal_bush.lsys", 3, 0},
                      Twin{"plants/dialects/fractal_tree.crankshaw", "plants/fractal_tree.lsys", 5, 0},
                      Twin{"plants/dialects/anabaena.crankshaw", "plants/anabaena.lsys", 5, 0},
                      Twin{"plants/dialects/decreasing_tree.crankshaw", "plants/decreasing_tree.lsys", 8, 0},
                      Twin{"plants/dialects/gravity_tree_2d.crankshaw", "plants/gravity_tree_2d.lsys", 6, 0},
                      Twin{"plants/dialects/conditions.crankshaw", "plants/conditions.lsys", 5, 0},
                      Twin{"plants/dialects/stochastic.crankshaw", "plants/stochastic.lsys", 5, 7},
                      Twin{"plants/dialects/tree_7_1.crankshaw", "plants/dialects/tree_7_1.lsys", 6, 0},
                      Twin{"plants/dialects/pine_tree_7_3.crankshaw", "plants/dialects/pine_tree_7_3.lsys", 5, 0},
                      Twin{"plants/dialects/robbins_sample_a.robbins", "plants/dialects/robbins_sample_a.lsys", 11, 0},
                      Twin{"plants/dialects/robbins_first_example.robbins",
                           "plants/dialects/robbins_first_example.lsys", 4, 0},
                      Twin{"plants/dialects/fig38_tree.plantlang", "plants/dialects/fig38_tree.lsys", 12, 0},
                      Twin{"plants/dialects/stochastic_bush.plantlang", "plants/dialects/stochastic_bush.lsys", 5, 3}),
    [](const auto& info) {
        std::string name = info.param.dialectFile;
        name = name.substr(name.rfind('/') + 1);
        for (char& c : name)
            if (c == '.') c = '_';
        return name;
    });

// The module counts of the source documents' worked examples are checked on the
// dialect files too, next to their native twins, in tests/lsystem/reference_test.cpp.

TEST(CrankshawReference, StochasticSameSeedSameStringOtherSeedOtherString) {
    Grammar grammar = loadOk("plants/dialects/stochastic.crankshaw");
    std::string first = toString(deriveSteps(grammar, 5, 11), grammar.symbols);
    EXPECT_EQ(toString(deriveSteps(grammar, 5, 11), grammar.symbols), first);
    EXPECT_NE(toString(deriveSteps(grammar, 5, 12), grammar.symbols), first);
}

// The native twin in data/plants spells Robbins' symbols differently: compare
// the counts of every symbol through the renaming.
TEST(RobbinsReference, SampleASymbolCountsMatchTheOtherNativeTwin) {
    Grammar robbins = loadOk("plants/dialects/robbins_sample_a.robbins");
    Grammar native = loadOk("plants/robbins_sample_a.lsys");
    const std::map<std::string, std::string> renamed = {{"'", "@Lm"}, {"!", "@Wm"}, {"t", "@Ts"}};
    for (int steps : {5, 11}) {
        std::map<std::string, size_t> expected;
        for (auto [name, count] : countsOf(deriveSteps(native, steps), native))
            expected[renamed.contains(name) ? renamed.at(name) : name] += count;
        EXPECT_EQ(countsOf(deriveSteps(robbins, steps), robbins), expected) << steps << " steps";
    }
}

// Each X draws one d and makes three Y, each Y one d and an X: the X triple
// every two steps, and 12 steps give 3 + 4 (1 + 3 + ... + 243) = 1 459 F.
TEST(PlantlangReference, Fig38SettingsAndFCount) {
    Grammar grammar = loadOk("plants/dialects/fig38_tree.plantlang");
    EXPECT_EQ(grammar.derivationLength, 12);
    EXPECT_DOUBLE_EQ(grammar.angle, 30.0);
    std::map<std::string, size_t> counts = countsOf(deriveSteps(grammar, 12), grammar);
    EXPECT_EQ(counts["F"], 1459u);
    EXPECT_EQ(counts["X"], 729u);
}

} // namespace
} // namespace lsys::test
