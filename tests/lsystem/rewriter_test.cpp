// The rewriter: thread-count independence, the D0L fast path against the
// general path, decomposition, interpretation and the module budget.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <vector>

#include "lsystem/common/error.h"
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

// Parameters print as printf's "%g" prints them (cpfg's string files do), for
// every kind of float: the text must be byte-comparable with cpfg's.
TEST(LsysModuleText, ParametersPrintAsPrintfG) {
    std::vector<float> values{0.0f, -0.0f,       1e-5f,     1e-4f,   100000.0f, 1e6f,
                              0.1f, 1.0f / 3.0f, 123456.5f, 3.4e38f, -2.5e-7f};
    RandomStream random = RandomStream::forModule(7, 0, 0);
    for (int i = 0; i < 2000; ++i)
        values.push_back(static_cast<float>((random.uniform() - 0.5) * std::pow(10.0, 12.0 * random.uniform() - 6.0)));
    ModuleString string;
    for (float value : values) string.push(kPush, std::span<const float>(&value, 1));
    SymbolTable symbols;
    std::string expected;
    char buffer[64];
    for (float value : values) {
        std::snprintf(buffer, sizeof buffer, "[(%g)", static_cast<double>(value));
        expected += buffer;
    }
    EXPECT_EQ(toString(string, symbols), expected);
}

// lsys derive --print writes a long string a megabyte at a time; cpfg's
// line layout runs on across the chunks.
TEST(LsysModuleText, LongStringsAreWrittenInChunksWithCpfgsLines) {
    Grammar grammar = parseOk("Axiom: A(1)\nA(x) --> F(x)[+A(x/3)]A(x*2)\n");
    const ModuleString string = derive(grammar, stepsOf(17)); // about 5 MB of text
    std::vector<std::string> chunks;
    writeText(string, grammar.symbols, TextLayout::Cpfg, [&](std::string_view chunk) { chunks.emplace_back(chunk); });
    ASSERT_GE(chunks.size(), 3u);
    std::string joined;
    for (const std::string& chunk : chunks) {
        EXPECT_LE(chunk.size(), (size_t(1) << 20) + 64);
        joined += chunk;
    }
    size_t lines = 0;
    for (size_t begin = 0; begin < joined.size();) {
        const size_t end = joined.find('\n', begin);
        ASSERT_NE(end, std::string::npos);
        const std::string_view line(joined.data() + begin, end - begin);
        const size_t counted = line.size() - static_cast<size_t>(std::count(line.begin(), line.end(), ','));
        if (end + 1 < joined.size()) {
            EXPECT_GE(counted, 70u) << "line " << lines;
        }
        EXPECT_LT(counted, 70u + 40u) << "line " << lines;
        begin = end + 1;
        ++lines;
    }
    EXPECT_GT(lines, 1000u);
}

// lsys derive --compare: a derived string against one written by cpfg.
TEST(LsysModuleText, FirstDifferenceFromAStringFile) {
    Grammar grammar = parseOk("Axiom: A(1)\nA(x) --> F(x)[+A(x/3)]A(x*2)\n");
    const ModuleString string = derive(grammar, stepsOf(3));
    const std::string text = toCpfgString(string, grammar.symbols);
    ASSERT_NE(text.find('\n'), text.size() - 1); // a line break inside, as cpfg writes long strings
    EXPECT_EQ(firstDifference(string, grammar.symbols, text), std::nullopt);
    // Within 1e-4 relative: cpfg's float arithmetic may round differently in the last digits.
    std::string close = toString(string, grammar.symbols);
    close.replace(close.find("0.333333"), 8, "0.333334");
    EXPECT_EQ(firstDifference(string, grammar.symbols, close), std::nullopt);
    std::string far = toString(string, grammar.symbols);
    far.replace(far.find("0.333333"), 8, "0.334");
    std::optional<std::string> difference = firstDifference(string, grammar.symbols, far);
    ASSERT_TRUE(difference);
    EXPECT_NE(difference->find("another parameter value: derived F(0.333333), the text has F(0.334)["),
              std::string::npos)
        << *difference;
    difference = firstDifference(string, grammar.symbols, toString(string, grammar.symbols) + "B");
    ASSERT_TRUE(difference);
    EXPECT_NE(difference->find("the text goes on"), std::string::npos);
    difference = firstDifference(string, grammar.symbols, "F(1)[+F");
    ASSERT_TRUE(difference);
    EXPECT_NE(difference->find("module 3: another parameter count"), std::string::npos) << *difference;
}

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

// Tools show a long derivation's progress from this: every step, in order,
// with the string's size after it.
TEST(LsysRewriter, EachStepIsReportedWithTheStringsSize) {
    Grammar grammar = parseOk("Axiom: A\nA --> AB\n");
    DeriveOptions options = stepsOf(4);
    std::vector<std::tuple<int, int, size_t>> reported;
    options.onStep = [&](int step, int steps, size_t modules) { reported.emplace_back(step, steps, modules); };
    EXPECT_EQ(derive(grammar, options).size(), 5u);
    const std::vector<std::tuple<int, int, size_t>> expected{{1, 4, 2}, {2, 4, 3}, {3, 4, 4}, {4, 4, 5}};
    EXPECT_EQ(reported, expected);
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

// cpfg decomposes only what each step makes (generate.c, ApplyProd), so the
// axiom's S unfolds during the first step, and the C made then is rewritten
// by one step fewer than natively.
TEST(LsysRewriter, DecomposeAxiomNoLeavesTheAxiomToTheFirstStep) {
    const std::string rules = "Axiom: S\nC(n) --> C(n + 1)\ndecomposition:\nS --> C(0)\n";
    EXPECT_EQ(derived("decompose axiom: no\n" + rules, 0), "S");
    EXPECT_EQ(derived("decompose axiom: no\n" + rules, 2), "C(1)");
    EXPECT_EQ(derived("decompose axiom: yes\n" + rules, 2), "C(2)");
    EXPECT_EQ(derived(rules, 2), "C(2)");
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
