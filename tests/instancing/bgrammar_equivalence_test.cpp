// The b-grammar generates exactly derive()'s word: for every plant file, with
// and without the interpretation rules, whichever way it was built; its
// counts equal the counts of that word; its nodes are legal and shared.

#include "instancing_test_support.h"
#include "lsystem/common/error.h"

namespace lsys::test {
namespace {

ModuleString interpreted(const Grammar& grammar) { return applyInterpretation(grammar, derive(grammar)); }

void expectGeneratesWord(const Grammar& grammar, const BGrammar& graph, const ModuleString& word) {
    expectSameWord(expand(graph), word, grammar.symbols);
    EXPECT_EQ(countModules(graph), histogram(word, grammar.symbols.size()));
    EXPECT_EQ(graph.nodes.back().modules, word.size());
}

TEST(BGrammarEquivalence, EveryPlantFileGeneratesTheDerivedWord) {
    for (const std::string& file : allPlantFiles()) {
        SCOPED_TRACE(file);
        Grammar grammar = loadOk(file);
        expectGeneratesWord(grammar, buildBGrammar(grammar), derive(grammar));
        BGrammarOptions options;
        options.interpreted = true;
        BGrammar graph = buildBGrammar(grammar, options);
        EXPECT_TRUE(graph.interpreted);
        expectGeneratesWord(grammar, graph, interpreted(grammar));
    }
}

TEST(BGrammarEquivalence, ContextFreeDeterministicFilesAreBuiltFromTheRules) {
    for (const char* file : {"plants/fractal_bush.lsys", "plants/decreasing_tree.lsys", "plants/leafy_plant.lsys",
                             "plants/monopodial_tree.lsys", "plants/dialects/tree_7_1.crankshaw"})
        EXPECT_EQ(buildBGrammar(loadOk(file)).method, BGrammarMethod::Memoised) << file;
    for (const char* file : {"plants/hogeweg_1_31a.lsys", "plants/context_benchmark.lsys", "plants/stochastic.lsys"})
        EXPECT_EQ(buildBGrammar(loadOk(file)).method, BGrammarMethod::Compressed) << file;
}

TEST(BGrammarEquivalence, CutBranchesAreDerivedAndCompressed) {
    // '%' removes the rest of its branch after every step, beyond the module's own subtree.
    Grammar grammar = parseOk("Axiom: A(0)\nA(x) --> F[+A(x+1)]B(x)A(x+1)\nB(x) : x > 1 --> %\n");
    BGrammarOptions options;
    options.steps = 6;
    BGrammar graph = buildBGrammar(grammar, options);
    EXPECT_EQ(graph.method, BGrammarMethod::Compressed);
    expectGeneratesWord(grammar, graph, derive(grammar, stepsOf(6)));
}

// Every node but the axiom is legal, used at least twice (§4.4) and has a
// body of two items or more (§4.3); every reference points backwards.
TEST(BGrammarEquivalence, NodesAreLegalSharedAndInTopologicalOrder) {
    for (const std::string& file : allPlantFiles()) {
        SCOPED_TRACE(file);
        Grammar grammar = loadOk(file);
        BGrammar graph = buildBGrammar(grammar);
        const std::vector<uint32_t> uses = referenceCounts(graph);
        for (uint32_t node = 0; node + 1 < graph.nodes.size(); ++node) {
            EXPECT_TRUE(nodeIsLegal(graph, node)) << "node " << node;
            EXPECT_TRUE(graph.nodes[node].legal()) << "node " << node;
            EXPECT_GE(uses[node], 2u) << "node " << node;
            EXPECT_GE(graph.nodes[node].bodyLength, 2u) << "node " << node;
            for (const BodyItem& item : graph.bodyOf(node)) EXPECT_TRUE(!item.isNode() || item.index < node);
        }
    }
}

TEST(BGrammarEquivalence, DecompositionInterpretationAndErasure) {
    Grammar grammar = parseOk("Axiom: A(1)E\n"
                              "A(x) : x < 40 --> S(x)[+A(x*2)]E A(x+1)\n"
                              "E -->\n"
                              "decomposition:\nmaximum depth: 3\nS(x) --> T(x)T(x+1)\nT(x) : x > 2 --> U(x)V\n"
                              "interpretation:\nV --> [F(1)]F(2)\n");
    for (int steps : {0, 1, 2, 5, 9}) {
        SCOPED_TRACE(steps);
        BGrammarOptions options;
        options.steps = steps;
        expectGeneratesWord(grammar, buildBGrammar(grammar, options), derive(grammar, stepsOf(steps)));
        options.interpreted = true;
        expectGeneratesWord(grammar, buildBGrammar(grammar, options),
                            applyInterpretation(grammar, derive(grammar, stepsOf(steps))));
    }
}

// Rules whose successors pop below their start make illegal nodes; they are
// inlined into their users, so the word stays exact and every node legal.
TEST(BGrammarEquivalence, IllegalNodesAreInlined) {
    Grammar grammar = parseOk("Axiom: [[[[[[[[B]]]]]]]]\nB --> F]B[B\n");
    BGrammarOptions options;
    options.steps = 6;
    BGrammar graph = buildBGrammar(grammar, options);
    expectGeneratesWord(grammar, graph, derive(grammar, stepsOf(6)));
    for (uint32_t node = 0; node + 1 < graph.nodes.size(); ++node) EXPECT_TRUE(nodeIsLegal(graph, node));
    EXPECT_EQ(graph.nodes.size(), 1u); // every B pops below its start: all of it is inlined into the axiom
}

TEST(BGrammarEquivalence, SingleModuleSuccessorsAreSubstituted) {
    // A(x) --> A(x+1) forever: every step substitutes, no node is made.
    Grammar grammar = parseOk("Axiom: A(0)F\nA(x) --> A(x+1)\n");
    BGrammarOptions options;
    options.steps = 5000;
    BGrammar graph = buildBGrammar(grammar, options);
    EXPECT_EQ(graph.nodes.size(), 1u);
    expectGeneratesWord(grammar, graph, derive(grammar, stepsOf(5000)));
}

TEST(BGrammarEquivalence, RewriteModuleMatchesOneStepOfDerive) {
    Grammar grammar = loadOk("plants/stochastic.lsys");
    for (uint64_t seed = 0; seed < 20; ++seed) {
        DeriveOptions derivation = stepsOf(1);
        derivation.seed = seed;
        ModuleString axiom = axiomString(grammar, seed);
        ModuleString rewritten;
        // derive() numbers the passes of step s from s * 1024; the axiom is one module at position 0.
        rewriteModule(grammar.rules, axiom.symbols[0], axiom.parameters(0), {seed, 1024, 0}, rewritten);
        expectSameWord(rewritten, derive(grammar, derivation), grammar.symbols);
    }
    Grammar contextual = loadOk("plants/context_benchmark.lsys");
    ModuleString out;
    EXPECT_THROW(rewriteModule(contextual.rules, 0, {}, {}, out), std::invalid_argument);
}

TEST(BGrammarEquivalence, ExpandRespectsItsBudget) {
    BGrammarOptions options;
    options.steps = 6;
    BGrammar graph = buildBGrammar(loadOk("plants/fractal_bush.lsys"), options);
    EXPECT_THROW(expand(graph, 1000), DerivationError);
}

TEST(BGrammarBudget, TooManyNodesIsAClearError) {
    BGrammarOptions options;
    options.limits.maxNodes = 5;
    options.steps = 9;
    try {
        buildBGrammar(loadOk("plants/fractal_bush.lsys"), options);
        FAIL() << "expected a budget error";
    } catch (const DerivationError& error) {
        EXPECT_NE(std::string(error.what()).find("b-grammar budget exceeded: more than 5 nodes"), std::string::npos)
            << error.what();
    }
    options.limits.maxNodes = 10; // 8 shared nodes, the axiom, and while building the one inlined into it
    EXPECT_NO_THROW(buildBGrammar(loadOk("plants/fractal_bush.lsys"), options));
}

TEST(BGrammarBudget, TooManyBodyItemsIsAClearError) {
    BGrammarOptions options;
    options.limits.maxItems = 100;
    try {
        buildBGrammar(loadOk("plants/monopodial_tree.lsys"), options);
        FAIL() << "expected a budget error";
    } catch (const DerivationError& error) {
        EXPECT_NE(std::string(error.what()).find("more than 100 body items"), std::string::npos) << error.what();
    }
    // A chain of single-module successors makes no item, but its keys count.
    Grammar chain = parseOk("Axiom: A(0)\nA(x) --> A(x+1)\n");
    options.steps = 1000;
    EXPECT_THROW(buildBGrammar(chain, options), DerivationError);
    // A decomposition that doubles every pass is stopped by the same budget.
    Grammar doubling = parseOk("Axiom: S\ndecomposition:\nmaximum depth: 30\nS --> SS\n");
    EXPECT_THROW(buildBGrammar(doubling, options), DerivationError);
}

TEST(BGrammarBudget, CountsPastTwoToTheSixtyFourAreAnError) {
    Grammar doubling = parseOk("Axiom: F\nF --> FF\n");
    BGrammarOptions options;
    options.steps = 70; // 2^70 modules
    EXPECT_THROW(buildBGrammar(doubling, options), DerivationError);
    options.steps = 63;
    EXPECT_EQ(countModules(buildBGrammar(doubling, options))[*doubling.symbols.find("F")], uint64_t{1} << 63);
}

} // namespace
} // namespace lsys::test
