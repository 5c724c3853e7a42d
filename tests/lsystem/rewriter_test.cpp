// The rewriter: thread-count independence, the D0L fast path against the
// general path, decomposition, interpretation and the module budget.

#include "lsystem/error.h"
#include "test_support.h"

namespace lsys::test {
namespace {

void expectIdentical(const ModuleString& a, const ModuleString& b) {
    EXPECT_EQ(a.symbols, b.symbols);
    EXPECT_EQ(a.params, b.params);
    EXPECT_EQ(a.hasParameters(), b.hasParameters());
    if (a.hasParameters() && b.hasParameters()) {
        EXPECT_EQ(a.paramStart, b.paramStart);
    }
}

class LsysThreadIndependence : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(LsysThreadIndependence, TwoThreadsGiveTheSameStringAsOne) {
    auto [file, steps] = GetParam();
    Grammar grammar = loadOk(file);
    DeriveOptions single = stepsOf(steps);
    single.threads = 1;
    DeriveOptions parallel = stepsOf(steps);
    parallel.threads = 2;
    parallel.parallelThreshold = 1; // split even the smallest strings
    DeriveOptions many = parallel;
    many.threads = 5;
    ModuleString reference = derive(grammar, single);
    expectIdentical(derive(grammar, parallel), reference);
    expectIdentical(derive(grammar, many), reference);
}

INSTANTIATE_TEST_SUITE_P(
    Rewriter, LsysThreadIndependence,
    ::testing::Values(std::pair{"plants/fractal_bush.lsys", 4}, std::pair{"plants/decreasing_tree.lsys", 8},
                      std::pair{"plants/context_benchmark.lsys", 16}, std::pair{"plants/stochastic.lsys", 5},
                      std::pair{"plants/context_brackets.lsys", 2}, std::pair{"plants/robbins_sample_a.lsys", 7}),
    [](const auto& info) {
        std::string name = info.param.first;
        name = name.substr(name.find('/') + 1);
        return name.substr(0, name.find('.'));
    });

TEST(LsysRewriter, RandomParametersDoNotDependOnThreads) {
    Grammar grammar = parseOk("Axiom: A(1)\nA(x) --> A(x+ran(1))[B(nran(0,1))]A(ran(x))\n");
    DeriveOptions single = stepsOf(8);
    single.threads = 1;
    DeriveOptions parallel = stepsOf(8);
    parallel.parallelThreshold = 1;
    expectIdentical(derive(grammar, parallel), derive(grammar, single));
}

TEST(LsysRewriter, FastPathMatchesGeneralPath) {
    // A condition that always holds forces the general path for the same rules.
    const std::string rules = "angle: 25\nAxiom: X\nX --> F-[[X]+X]+F[+FX]-X\nF --> FF\n";
    const std::string general = "angle: 25\nAxiom: X\nX : 1 --> F-[[X]+X]+F[+FX]-X\nF : 1 --> FF\n";
    Grammar a = parseOk(rules);
    Grammar b = parseOk(general);
    EXPECT_EQ(toString(derive(a, stepsOf(6)), a.symbols), toString(derive(b, stepsOf(6)), b.symbols));
}

TEST(LsysRewriter, ZeroStepsGiveTheAxiom) {
    EXPECT_EQ(derived("#define a 2\nAxiom: A(a*3)[B]\nA(x) --> C\n", 0), "A(6)[B]");
}

TEST(LsysRewriter, ModulesWithoutRuleAreCopiedWithParameters) {
    EXPECT_EQ(derived("Axiom: A(1,2)B(3)C\nC --> D(4)\n", 1), "A(1,2)B(3)D(4)");
}

TEST(LsysRewriter, ParametersAreStoredAsFloat) {
    EXPECT_EQ(derived("Axiom: A(1)\nA(x) --> A(x/3)\n", 1), "A(0.333333)");
}

TEST(LsysRewriter, DecompositionIsAppliedAfterEveryStep) {
    // A grows one S per step; S decomposes into T then U (two levels deep).
    EXPECT_EQ(derived("Axiom: A\nA --> AS\ndecomposition:\nmaximum depth: 4\nS --> T\nT --> U\n", 2), "AUU");
    // With depth 1 only one level is applied after each step: the older S has had two.
    EXPECT_EQ(derived("Axiom: A\nA --> AS\ndecomposition:\nmaximum depth: 1\nS --> T\nT --> U\n", 2), "ATU");
}

TEST(LsysRewriter, DecompositionAppliesToTheAxiom) {
    EXPECT_EQ(derived("Axiom: S\ndecomposition:\nS --> F(1)F(2)\n", 0), "F(1)F(2)");
}

TEST(LsysRewriter, RecursiveDecompositionStopsAtMaximumDepth) {
    EXPECT_EQ(derived("Axiom: S\ndecomposition:\nmaximum depth: 3\nS --> FS\n", 0), "FFFS");
}

TEST(LsysRewriter, CutRemovesTheRestOfTheBranch) {
    EXPECT_EQ(derived("Axiom: A[BA[A]C]A\nB --> %\n", 1), "A[]A");
    EXPECT_EQ(derived("Axiom: F(1)A(2)[A(3)]F\nA(x) : x > 2 --> %\n", 1), "F(1)A(2)[]F");
    EXPECT_EQ(derived("Axiom: AB\nA --> %\n", 1), "");
}

TEST(LsysRewriter, InterpretationIsOnlyForTheTurtle) {
    Grammar grammar = parseOk("Axiom: A\nA --> AL\ninterpretation:\nL --> [+F]\n");
    ModuleString string = derive(grammar, stepsOf(2));
    EXPECT_EQ(toString(string, grammar.symbols), "ALL");
    EXPECT_EQ(toString(applyInterpretation(grammar, string), grammar.symbols), "A[+F][+F]");
}

TEST(LsysRewriter, ModuleBudgetStopsWithAClearError) {
    Grammar grammar = loadOk("plants/fractal_bush.lsys");
    DeriveOptions options = stepsOf(7);
    options.maxModules = 100000; // step 5 gives 88 940 modules, step 6 about 711 500
    try {
        derive(grammar, options);
        FAIL() << "expected the budget to be exceeded";
    } catch (const DerivationError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("budget"), std::string::npos) << message;
        EXPECT_NE(message.find("step 6"), std::string::npos) << message;
        EXPECT_NE(message.find("100000"), std::string::npos) << message;
    }
    options.steps = 5;
    EXPECT_EQ(derive(grammar, options).size(), 88940u);
}

TEST(LsysRewriter, ModuleBudgetAppliesToTheGeneralPath) {
    Grammar grammar = loadOk("plants/decreasing_tree.lsys");
    for (int threads : {1, 2}) {
        DeriveOptions options = stepsOf(19);
        options.threads = threads;
        options.parallelThreshold = 1;
        options.maxModules = 5000;
        EXPECT_THROW(derive(grammar, options), DerivationError) << threads;
    }
}

TEST(LsysRewriter, ModuleBudgetCountsCopiedModulesToo) {
    // The budget is passed mostly by modules copied unchanged (a fuzzer found
    // the copies overrunning the output buffer once the budget was passed).
    Grammar grammar = parseOk("Axiom: A" + std::string(200, 'X') + "\nA --> AAAAAAAAAA\n");
    for (int threads : {1, 2}) {
        DeriveOptions options = stepsOf(1);
        options.threads = threads;
        options.parallelThreshold = 1;
        options.maxModules = 50;
        EXPECT_THROW(derive(grammar, options), DerivationError) << threads;
        options.maxModules = 210;
        EXPECT_EQ(derive(grammar, options).size(), 210u) << threads;
    }
}

TEST(LsysRewriter, ModuleBudgetAppliesToDecomposition) {
    Grammar grammar = parseOk("Axiom: S\ndecomposition:\nmaximum depth: 100\nS --> SS\n");
    DeriveOptions options = stepsOf(0);
    options.maxModules = 1000;
    EXPECT_THROW(derive(grammar, options), DerivationError);
}

} // namespace
} // namespace lsys::test
