// SEQUITUR with bracket legality (Calgary b-grammar thesis, ch. 6): the grammar
// generates the input exactly, no rule pops below its start, rules that leave
// branches open start with '[', every rule is used twice and no digram repeats
// where a rule may be formed.

#include <random>
#include <set>

#include "instancing_test_support.h"
#include "lsystem/common/error.h"
#include "lsystem/instancing/sequitur.h"

namespace lsys::test {
namespace {

// A word of the given text, one module per character ('[' and ']' are brackets).
ModuleString wordOf(const std::string& text, SymbolTable& symbols) {
    ModuleString word;
    for (char c : text) word.push(symbols.intern(std::string(1, c)));
    return word;
}

void expectLegalRules(const BGrammar& graph) {
    for (uint32_t node = 0; node + 1 < graph.nodes.size(); ++node) {
        EXPECT_TRUE(nodeIsLegal(graph, node)) << "rule " << node;
        std::vector<SymbolId> word;
        appendNodeWord(graph, node, word);
        if (graph.nodes[node].depthChange > 0) {
            EXPECT_EQ(word.front(), kPush) << "rule " << node << " leaves a branch open";
        }
    }
}

void expectRulesUsedTwice(const BGrammar& graph) {
    const std::vector<uint32_t> uses = referenceCounts(graph);
    for (uint32_t node = 0; node + 1 < graph.nodes.size(); ++node) EXPECT_GE(uses[node], 2u) << "rule " << node;
}

TEST(Sequitur, ContextSensitiveWordsAreCompressedExactly) {
    for (const char* file : {"plants/hogeweg_1_31a.lsys", "plants/hogeweg_1_31b.lsys", "plants/hogeweg_1_31c.lsys",
                             "plants/hogeweg_1_31d.lsys", "plants/hogeweg_1_31e.lsys", "plants/context_benchmark.lsys",
                             "plants/context_brackets.lsys"}) {
        SCOPED_TRACE(file);
        Grammar grammar = loadOk(file);
        ModuleString word = derive(grammar);
        BGrammar graph = compressWord(word, grammar.symbols.size());
        expectSameWord(expand(graph), word, grammar.symbols);
        EXPECT_EQ(countModules(graph), histogram(word, grammar.symbols.size()));
        expectLegalRules(graph);
        expectRulesUsedTwice(graph);
        const double ratio = static_cast<double>(word.size()) / static_cast<double>(graph.body.size());
        std::cout << file << ": " << word.size() << " modules in " << graph.nodes.size() << " rules, "
                  << graph.body.size() << " body items (" << ratio << ":1)\n";
        if (word.size() > 10'000) {
            EXPECT_GT(ratio, 5.0);
        }
    }
}

TEST(Sequitur, NoDigramRepeatsWithoutBrackets) {
    std::mt19937 random(5);
    for (int round = 0; round < 50; ++round) {
        SymbolTable symbols;
        std::string text;
        const int alphabet = 2 + round % 4;
        for (int i = 0; i < 3000; ++i) text += static_cast<char>('a' + random() % alphabet);
        ModuleString word = wordOf(text, symbols);
        BGrammar graph = compressWord(word, symbols.size());
        expectSameWord(expand(graph), word, symbols);
        expectRulesUsedTwice(graph);
        // Digram uniqueness: a pair of adjacent items appears once, except as overlapping runs "xxx".
        std::set<std::pair<uint64_t, uint64_t>> seen;
        for (uint32_t node = 0; node < graph.nodes.size(); ++node) {
            std::span<const BodyItem> body = graph.bodyOf(node);
            for (size_t i = 0; i + 1 < body.size(); ++i) {
                auto key = [](const BodyItem& item) { return uint64_t{item.index} << 1 | item.isNode(); };
                const bool overlapping = i > 0 && body[i - 1] == body[i] && body[i] == body[i + 1];
                if (!overlapping) {
                    EXPECT_TRUE(seen.insert({key(body[i]), key(body[i + 1])}).second) << "round " << round;
                }
            }
        }
        EXPECT_LT(graph.body.size(), word.size() / 2) << "round " << round;
    }
}

TEST(Sequitur, RulesRespectBracketLegality) {
    std::mt19937 random(9);
    const std::string alphabet = "F+-[]";
    for (int round = 0; round < 100; ++round) {
        SymbolTable symbols;
        std::string text;
        int depth = 0;
        for (int i = 0; i < 2000; ++i) {
            char c = alphabet[random() % alphabet.size()];
            if (c == ']' && depth == 0 && round % 2 == 0) c = 'F'; // odd rounds pop below the start too
            depth += c == '[' ? 1 : c == ']' ? -1 : 0;
            text += c;
        }
        ModuleString word = wordOf(text, symbols);
        BGrammar graph = compressWord(word, symbols.size());
        expectSameWord(expand(graph), word, symbols);
        expectLegalRules(graph);
        expectRulesUsedTwice(graph);
    }
}

TEST(Sequitur, BranchesBecomeRules) {
    // After the Calgary b-grammar thesis' example in §6.2: rules gather whole branches, never "F[" or "F]"
    // (SEQUITUR is greedy, so the two copies of "[-FF[+FF][-FF]]" are parsed differently).
    SymbolTable symbols;
    ModuleString word = wordOf("FFFF[+FF][-FF[+FF][-FF]]FF[+FF][-FF[+FF][-FF]]", symbols);
    BGrammar graph = compressWord(word, symbols.size());
    expectSameWord(expand(graph), word, symbols);
    expectLegalRules(graph);
    std::set<std::string> rules;
    for (uint32_t node = 0; node + 1 < graph.nodes.size(); ++node) {
        std::vector<SymbolId> expansion;
        appendNodeWord(graph, node, expansion);
        std::string text;
        for (SymbolId symbol : expansion) text += symbols.name(symbol);
        rules.insert(text);
    }
    EXPECT_TRUE(rules.count("[+FF]")) << ::testing::PrintToString(rules);
    EXPECT_TRUE(rules.count("[-FF]")) << ::testing::PrintToString(rules);
    for (const std::string& rule : rules) {
        EXPECT_NE(rule.substr(0, 2), "F[") << rule;
        EXPECT_NE(rule.back(), '[') << rule;
    }
}

TEST(Sequitur, ParametersTellModulesApart) {
    Grammar grammar = parseOk("Axiom: A(1)A(2)A(1)A(2)A(1)A(2)\n");
    ModuleString word = derive(grammar);
    BGrammar graph = compressWord(word, grammar.symbols.size());
    expectSameWord(expand(graph), word, grammar.symbols);
    EXPECT_EQ(graph.modules.size(), 2u);
    EXPECT_EQ(graph.nodes.size(), 2u); // A(1)A(2) and the axiom
}

TEST(Sequitur, LongWordsAreRefusedByTheBudget) {
    SymbolTable symbols;
    ModuleString word = wordOf(std::string(1000, 'F'), symbols);
    BGrammarLimits limits;
    limits.maxItems = 100;
    EXPECT_THROW(compressWord(word, symbols.size(), limits), DerivationError);
    limits.maxItems = 1000;
    EXPECT_NO_THROW(compressWord(word, symbols.size(), limits));
    EXPECT_EQ(compressWord(ModuleString{}, symbols.size()).nodes.back().modules, 0u);
}

} // namespace
} // namespace lsys::test
