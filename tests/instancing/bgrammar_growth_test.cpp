// Calgary b-grammar thesis, §4.5: for a D0L system the b-grammar grows
// linearly with the number of steps while the word grows geometrically, so a
// word of 134 M segments is counted from a few nodes.

#include <map>

#include "instancing_test_support.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys::test {
namespace {

constexpr const char* kBushSuccessor = "FF+[+F-F-F]-[-F+F+F]";

Grammar bush() { return parseOk(std::string("Axiom: F\nF --> ") + kBushSuccessor + "\n"); }

BGrammar bushGraph(const Grammar& grammar, int steps) {
    BGrammarOptions options;
    options.steps = steps;
    return buildBGrammar(grammar, options);
}

// The bush's module counts after some steps, by the recurrence on the
// successor's letters: only F is rewritten, each F adds one successor.
std::map<char, uint64_t> bushCounts(int steps) {
    std::map<char, uint64_t> counts{{'F', 1}};
    for (int step = 0; step < steps; ++step) {
        const uint64_t rewritten = counts['F'];
        counts['F'] = 0;
        for (char c : std::string(kBushSuccessor)) counts[c] += rewritten;
    }
    return counts;
}

TEST(BGrammarGrowth, NodesGrowLinearlyWhileTheWordGrowsGeometrically) {
    Grammar grammar = bush();
    const SymbolId f = *grammar.symbols.find("F");
    std::vector<size_t> nodes;
    std::vector<uint64_t> instances, segments;
    for (int steps = 1; steps <= 14; ++steps) {
        BGrammar graph = bushGraph(grammar, steps);
        InstanceGraphStats stats = instanceGraphStats(buildInstanceGraph(graph, grammar));
        nodes.push_back(graph.nodes.size());
        instances.push_back(stats.instances);
        segments.push_back(countModules(graph)[f]);
    }
    for (size_t i = 3; i + 1 < nodes.size(); ++i) {
        EXPECT_EQ(nodes[i + 1] - nodes[i], nodes[i] - nodes[i - 1]) << "steps " << i + 1;
        EXPECT_GT(nodes[i + 1], nodes[i]);
        EXPECT_EQ(instances[i + 1] - instances[i], instances[i] - instances[i - 1]) << "steps " << i + 1;
        EXPECT_EQ(segments[i + 1], 8 * segments[i]);
    }
}

TEST(BGrammarGrowth, NineStepBushIsCountedWithoutExpanding) {
    Grammar grammar = bush();
    BGrammar graph = bushGraph(grammar, 9);
    const std::vector<uint64_t> counts = countModules(graph);
    uint64_t total = 0;
    for (const auto& [c, count] : bushCounts(9)) {
        EXPECT_EQ(counts[*grammar.symbols.find(std::string(1, c))], count) << c;
        total += count;
    }
    EXPECT_EQ(counts[*grammar.symbols.find("F")], 134'217'728u);
    EXPECT_EQ(graph.nodes.back().modules, total);
    EXPECT_LT(graph.nodes.size(), 12u);
    InstanceGraphStats stats = instanceGraphStats(buildInstanceGraph(graph, grammar));
    EXPECT_EQ(stats.primitives, 134'217'728u);
    EXPECT_EQ(stats.joints, stats.primitives);
    EXPECT_EQ(stats.nodes, graph.nodes.size());
    EXPECT_LT(stats.bytesGraph, 10'000u);
    EXPECT_GT(stats.compression(), 1e6);
}

TEST(BGrammarGrowth, CountsMatchTheRecurrenceAtEveryStep) {
    Grammar grammar = bush();
    for (int steps = 0; steps <= 12; ++steps) {
        const std::vector<uint64_t> counts = countModules(bushGraph(grammar, steps));
        for (const auto& [c, count] : bushCounts(steps))
            EXPECT_EQ(counts[*grammar.symbols.find(std::string(1, c))], count) << steps;
    }
}

TEST(BGrammarGrowth, InstanceStatsCountEveryKindOfPrimitive) {
    // Per A: one F, one leaf surface, one sphere, one triangle; + and [ ] are not primitives.
    Grammar grammar = parseOk("Axiom: A\nA --> F[~leaf(1)]@O(1){.+f+f}AA\n");
    BGrammarOptions options;
    options.steps = 3;
    BGrammar graph = buildBGrammar(grammar, options);
    InstanceGraphStats stats = instanceGraphStats(buildInstanceGraph(graph, grammar));
    EXPECT_EQ(stats.joints, 7u); // 1 + 2 + 4 A were rewritten
    EXPECT_EQ(stats.primitives, 4u * 7u);
    // Nodes: A after 1 and 2 steps (the 3-step one is the axiom's only reference, inlined).
    EXPECT_EQ(stats.nodes, 3u);
    // Instances: 4 primitives placed directly in each of the three bodies,
    // 2 references in the bodies of A after 2 and 3 steps (the axiom's).
    EXPECT_EQ(stats.instances, 3u * 4u + 2u * 2u);
    EXPECT_EQ(stats.bytesFlat, stats.primitives * sizeof(Primitive));
}

} // namespace
} // namespace lsys::test
