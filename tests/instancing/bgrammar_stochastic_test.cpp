// Pseudo-stochastic b-grammars (Calgary b-grammar thesis, §5.1): with a
// randomness factor k a module is rewritten at most k ways per step, picked
// from the seed. The word is not derive()'s, but is reproducible and has its
// statistics.

#include <cmath>

#include "instancing_test_support.h"

namespace lsys::test {
namespace {

BGrammar pseudoStochastic(const Grammar& grammar, int k, uint64_t seed, int steps) {
    BGrammarOptions options;
    options.randomness = k;
    options.seed = seed;
    options.steps = steps;
    return buildBGrammar(grammar, options);
}

void expectSameGraph(const BGrammar& a, const BGrammar& b) {
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(a.body, b.body);
    EXPECT_EQ(a.params, b.params);
    EXPECT_EQ(expand(a).symbols, expand(b).symbols);
}

TEST(BGrammarStochastic, SameSeedGivesTheSameGraph) {
    for (const char* file :
         {"plants/stochastic.lsys", "plants/stochastic_bush.lsys", "plants/dialects/stochastic.crankshaw"}) {
        SCOPED_TRACE(file);
        Grammar grammar = loadOk(file);
        BGrammar first = pseudoStochastic(grammar, 4, 7, 6);
        EXPECT_EQ(first.method, BGrammarMethod::PseudoStochastic);
        expectSameGraph(first, pseudoStochastic(grammar, 4, 7, 6));
        EXPECT_NE(expand(first).symbols, expand(pseudoStochastic(grammar, 4, 8, 6)).symbols);
    }
}

// Every key (F, remaining steps) has at most k variants, so the graph has at
// most k nodes per step (plus the axiom); with k = 1 it is a D0L graph.
TEST(BGrammarStochastic, AtMostKVariantsPerModuleAndStep) {
    Grammar grammar = loadOk("plants/stochastic_bush.lsys");
    const int steps = 8;
    for (int k : {1, 2, 3, 5}) {
        SCOPED_TRACE(k);
        size_t most = 0;
        for (uint64_t seed = 0; seed < 10; ++seed) {
            BGrammar graph = pseudoStochastic(grammar, k, seed, steps);
            EXPECT_LE(graph.nodes.size(), static_cast<size_t>(k * steps + 1));
            most = std::max(most, graph.nodes.size());
        }
        if (k > 1) {
            EXPECT_GT(most, static_cast<size_t>(steps + 1)) << "variants should appear";
        }
    }
    // k = 1: every F at the same step grows the same way, as in a D0L system.
    BGrammar single = pseudoStochastic(grammar, 1, 3, steps);
    EXPECT_LE(single.nodes.size(), static_cast<size_t>(steps));
}

struct Sample {
    double mean = 0;
    double standardError = 0;
};

// Segments after some steps over many seeds: derive()'s (k = 0) or the pseudo-stochastic b-grammar's.
Sample segments(const Grammar& grammar, int k, int steps, int seeds) {
    const SymbolId f = *grammar.symbols.find("F");
    double sum = 0, squares = 0;
    for (int seed = 0; seed < seeds; ++seed) {
        double count;
        if (k == 0) {
            DeriveOptions options = stepsOf(steps);
            options.seed = static_cast<uint64_t>(seed);
            count = static_cast<double>(histogram(derive(grammar, options), grammar.symbols.size())[f]);
        } else {
            count =
                static_cast<double>(countModules(pseudoStochastic(grammar, k, static_cast<uint64_t>(seed), steps))[f]);
        }
        sum += count;
        squares += count * count;
    }
    const double mean = sum / seeds;
    return {mean, std::sqrt((squares / seeds - mean * mean) / seeds)};
}

// Each variant is an independent draw, so the expected segment count is the
// L-system's: (F per rewrite)^steps, whatever k.
TEST(BGrammarStochastic, SegmentCountsHaveDerivesMean) {
    const struct {
        const char* file;
        double segmentsPerRewrite;
    } cases[] = {{"plants/stochastic_bush.lsys", 5.0 / 3 + 3.0 / 3 + 3.0 / 3},
                 {"plants/stochastic.lsys", 0.33 * 5 + 0.33 * 3 + 0.34 * 3}};
    for (const auto& [file, perRewrite] : cases) {
        SCOPED_TRACE(file);
        Grammar grammar = loadOk(file);
        const double expected = std::pow(perRewrite, 5);
        for (int k : {0, 1, 2, 20}) {
            const Sample sample = segments(grammar, k, 5, 1000);
            EXPECT_NEAR(sample.mean, expected, 4 * sample.standardError) << "k = " << k;
        }
    }
}

TEST(BGrammarStochastic, RandomParametersAreSharedByVariant) {
    // ran() in a successor: values differ per variant, are reproducible, and
    // k bounds the distinct leaves: all the blades of grass come from k kinds.
    Grammar grammar = parseOk("Axiom: G(8)\nG(l) : l > 0 --> [+G(l-1)][-G(l-1)]\nG(l) : l == 0 --> B(ran(1))\n");
    BGrammar graph = pseudoStochastic(grammar, 3, 11, 9);
    ModuleString word = expand(graph);
    const SymbolId b = *grammar.symbols.find("B");
    std::vector<float> blades;
    for (size_t i = 0; i < word.size(); ++i)
        if (word.symbols[i] == b) blades.push_back(word.parameters(i)[0]);
    EXPECT_EQ(blades.size(), 256u);
    std::sort(blades.begin(), blades.end());
    const size_t kinds = static_cast<size_t>(std::unique(blades.begin(), blades.end()) - blades.begin());
    EXPECT_GE(kinds, 2u);
    EXPECT_LE(kinds, 3u);
    EXPECT_LE(graph.nodes.size(), 3u * 8u + 1u);
    expectSameGraph(graph, pseudoStochastic(grammar, 3, 11, 9));
}

TEST(BGrammarStochastic, WithoutARandomnessFactorTheWordIsExact) {
    Grammar grammar = loadOk("plants/stochastic_bush.lsys");
    for (uint64_t seed = 0; seed < 5; ++seed) {
        BGrammarOptions options;
        options.seed = seed;
        BGrammar graph = buildBGrammar(grammar, options);
        EXPECT_EQ(graph.method, BGrammarMethod::Compressed);
        DeriveOptions derivation;
        derivation.seed = seed;
        expectSameWord(expand(graph), derive(grammar, derivation), grammar.symbols);
    }
}

TEST(BGrammarStochastic, RandomDecompositionOrInterpretationIsExactWithoutAFactor) {
    for (const char* source : {"Axiom: A\nA --> A[+A]B\ndecomposition:\nB --> F(ran(1))\n",
                               "Axiom: A\nA --> A[+A]B\ninterpretation:\nB --> F(ran(1))\n"}) {
        SCOPED_TRACE(source);
        Grammar grammar = parseOk(source);
        BGrammarOptions options;
        options.steps = 4;
        options.interpreted = true;
        BGrammar graph = buildBGrammar(grammar, options);
        EXPECT_EQ(graph.method, BGrammarMethod::Compressed);
        expectSameWord(expand(graph), applyInterpretation(grammar, derive(grammar, stepsOf(4))), grammar.symbols);
    }
}

TEST(BGrammarStochastic, DeterministicGrammarsIgnoreTheFactor) {
    Grammar grammar = loadOk("plants/fractal_bush.lsys");
    BGrammar graph = pseudoStochastic(grammar, 5, 1, 6);
    EXPECT_EQ(graph.method, BGrammarMethod::Memoised);
    expectSameWord(expand(graph), derive(grammar, stepsOf(6)), grammar.symbols);
}

} // namespace
} // namespace lsys::test
