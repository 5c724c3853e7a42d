// Stochastic groups: alternatives are chosen with their probabilities, and
// the choice depends only on (seed, step, position).

#include <cmath>

#include "test_support.h"

namespace lsys::test {
namespace {

TEST(LsysStochastic, FrequenciesFollowTheProbabilities) {
    const int n = 40000;
    const std::string source = "Axiom: " + std::string(n, 'A') + "\nA --> B : 0.2\nA --> C : 0.3\nA --> D : 0.5\n";
    Grammar grammar = parseOk(source);
    for (uint64_t seed : {0ull, 1ull, 12345ull}) {
        DeriveOptions options = stepsOf(1);
        options.seed = seed;
        ModuleString string = derive(grammar, options);
        ASSERT_EQ(string.size(), static_cast<size_t>(n));
        for (auto [name, p] : {std::pair{"B", 0.2}, std::pair{"C", 0.3}, std::pair{"D", 0.5}}) {
            const double expected = n * p;
            const double sd = std::sqrt(n * p * (1 - p));
            EXPECT_NEAR(static_cast<double>(countOf(string, grammar, name)), expected, 5 * sd)
                << name << " seed " << seed;
        }
    }
}

TEST(LsysStochastic, ChoicesAreIndependentAcrossSteps) {
    // Each step is a fresh draw: after two steps of A -> A : 0.5 | B : 0.5, a quarter of the modules remain A.
    const int n = 40000;
    Grammar grammar = parseOk("Axiom: " + std::string(n, 'A') + "\nA --> A : 0.5\nA --> B : 0.5\n");
    ModuleString string = derive(grammar, stepsOf(2));
    const double sd = std::sqrt(n * 0.25 * 0.75);
    EXPECT_NEAR(static_cast<double>(countOf(string, grammar, "A")), n * 0.25, 5 * sd);
}

TEST(LsysStochastic, GroupWithConditionOnlyAppliesWhenItHolds) {
    Grammar grammar = parseOk("Axiom: A(1)A(-1)\nA(x) : x > 0 --> B : 0.5\nA(x) : x > 0 --> C : 0.5\n");
    std::string result = toString(derive(grammar, stepsOf(1)), grammar.symbols);
    EXPECT_TRUE(result == "BA(-1)" || result == "CA(-1)") << result;
}

TEST(LsysStochastic, ProbabilitiesMustSumToOne) {
    ParseResult result = parseLsystem("Axiom: A\nA --> B : 0.5\nA --> C : 0.4\n");
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, 2);
    EXPECT_NE(result.diagnostics[0].message.find("sum to 0.9"), std::string::npos) << result.diagnostics[0].message;
}

TEST(LsysStochastic, SumWithinToleranceIsAccepted) {
    EXPECT_TRUE(parseLsystem("Axiom: A\nA --> B : 1/3\nA --> C : 1/3\nA --> D : 1/3\n").ok());
    EXPECT_FALSE(parseLsystem("Axiom: A\nA --> B : 0.333\nA --> C : 0.333\nA --> D : 0.333\n").ok());
}

TEST(LsysStochastic, DifferentPredecessorsFormDifferentGroups) {
    ParseResult result = parseLsystem("Axiom: A\nA --> B : 0.5\nA --> C : 0.5\nB --> C : 0.5\nB --> D : 0.5\n");
    EXPECT_TRUE(result.ok());
    ParseResult wrong = parseLsystem("Axiom: A\nA --> B : 0.5\nB --> C : 0.5\n");
    EXPECT_EQ(wrong.diagnostics.size(), 2u);
}

TEST(LsysStochastic, RandomFunctionsAreReproducible) {
    Grammar grammar = parseOk("Axiom: A(0)A(0)A(0)\nA(x) --> A(ran(10)) B(nran(5, 1))\n");
    DeriveOptions options = stepsOf(3);
    options.seed = 3;
    const std::string first = toString(derive(grammar, options), grammar.symbols);
    EXPECT_EQ(toString(derive(grammar, options), grammar.symbols), first);
    options.seed = 4;
    EXPECT_NE(toString(derive(grammar, options), grammar.symbols), first);
}

TEST(LsysStochastic, SeedFromTheHeaderIsUsed) {
    const std::string rules = "Axiom: " + std::string(64, 'A') + "\nA --> B : 0.5\nA --> C : 0.5\n";
    Grammar a = parseOk("seed: 5\n" + rules);
    Grammar b = parseOk("seed: 6\n" + rules);
    DeriveOptions options = stepsOf(1);
    EXPECT_NE(toString(derive(a, options), a.symbols), toString(derive(b, options), b.symbols));
    options.seed = 6;
    EXPECT_EQ(toString(derive(a, options), a.symbols), toString(derive(b, stepsOf(1)), b.symbols));
}

} // namespace
} // namespace lsys::test
