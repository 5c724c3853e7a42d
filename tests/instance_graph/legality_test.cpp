// A node whose body pops below its start has no status function (Calgary
// b-grammar thesis, §4.2): it is interpreted inline, as part of the body that
// uses it, and the plant stays the turtle's. buildBGrammar already inlines such
// nodes, so the b-grammar here is written by hand.

#include "instance_graph_test_support.h"

namespace lsys::test {
namespace {

struct HandBGrammar {
    Grammar grammar = parseOk("Axiom: F+[]\n");
    BGrammar bgrammar;

    HandBGrammar() {
        bgrammar.symbolCount = grammar.symbols.size();
        bgrammar.interpreted = true;
    }
    BodyItem module(const char* name) {
        bgrammar.modules.push_back({*grammar.symbols.find(name), 0, 0});
        return {BodyItem::Kind::Module, static_cast<uint32_t>(bgrammar.modules.size() - 1)};
    }
    BodyItem node(std::vector<BodyItem> body) {
        BNode node;
        node.bodyStart = static_cast<uint32_t>(bgrammar.body.size());
        node.bodyLength = static_cast<uint32_t>(body.size());
        bgrammar.body.insert(bgrammar.body.end(), body.begin(), body.end());
        bgrammar.nodes.push_back(node);
        return {BodyItem::Kind::Node, static_cast<uint32_t>(bgrammar.nodes.size() - 1)};
    }
};

TEST(InstanceGraphLegality, NodesPoppingBelowTheirStartAreInlined) {
    HandBGrammar hand;
    const BodyItem twig = hand.node({hand.module("F"), hand.module("+"), hand.module("F")}); // legal, shared
    // "]F twig [": pops the state its user pushed, so it has no status function.
    const BodyItem illegal = hand.node({hand.module("]"), hand.module("F"), twig, hand.module("[")});
    hand.node({hand.module("F"), hand.module("["), hand.module("+"), twig, illegal, hand.module("+"), twig,
               hand.module("]"), twig, hand.module("["), illegal, twig, hand.module("]")});

    const InstanceGraph graph = buildInstanceGraph(hand.bgrammar, hand.grammar);
    for (const GraphObject& object : graph.objects) EXPECT_NE(object.node, illegal.index);
    size_t twigObjects = 0;
    for (const GraphObject& object : graph.objects) twigObjects += object.node == twig.index;
    EXPECT_EQ(twigObjects, 1u);

    const PlantAsset expected =
        interpretPlant(expand(hand.bgrammar), hand.grammar.symbols, turtleSettings(hand.grammar), SurfaceLibrary{});
    expectSamePlant(flatten(graph), expected);
    EXPECT_EQ(instanceGraphStats(graph).primitives, expected.primitives.size());
}

TEST(InstanceGraphLegality, TheWordMustBeTheInterpretedOne) {
    const Grammar grammar = parseOk("Axiom: A\nA --> AB\ninterpretation:\nB --> F\n");
    EXPECT_THROW(buildInstanceGraph(buildBGrammar(grammar), grammar), std::invalid_argument);
}

} // namespace
} // namespace lsys::test
