// Tropism makes a subtree's shape depend on its entry orientation (Calgary
// b-grammar thesis, §5.3). Objects are shared between entries whose tropism
// vector, seen from the entry frame, is the same (Theorem 5.1: the orientations
// differ by a rotation about T) — exactly with G = 0, within cells of pi/G
// otherwise.

#include <cmath>
#include <cstdio>

#include "instance_graph_test_support.h"

namespace lsys::test {
namespace {

size_t objectsOfNode(const InstanceGraph& graph, uint32_t node) {
    size_t count = 0;
    for (const GraphObject& object : graph.objects) count += object.node == node;
    return count;
}

// Fig 5.10: four branches rolled 0, 90, 180 and 270 degrees about T (here
// the start heading) and pitched 10 degrees draw one shape four times.
TEST(InstanceGraphTropism, BranchesRotatedAboutTheTropismVectorShareAnObject) {
    const Grammar grammar = parseOk("Axiom: [A]/(90)[A]/(90)[A]/(90)[A]\nA --> &(10)@Ts(0.3)FFFF\n");
    InstanceGraphOptions options;
    options.orientationGranularity = 16;
    const BGrammar bgrammar = interpretedBGrammar(grammar, 1);
    const InstanceGraph graph = buildInstanceGraph(bgrammar, grammar, options);
    ASSERT_EQ(graph.instances.size(), 4u);
    EXPECT_EQ(objectsOfNode(graph, graph.objects[graph.instances[0].object].node), 1u);
    expectSamePlant(flatten(graph), turtlePlant(grammar, 1));
}

// Branches entered at different angles to T bend differently: never shared exactly.
TEST(InstanceGraphTropism, DifferentAnglesToTheTropismVectorAreNotShared) {
    const Grammar grammar = parseOk("Axiom: [A][+(40)A][-(80)A]\nA --> @Ts(0.3)FFFF\n");
    const InstanceGraph graph = buildInstanceGraph(interpretedBGrammar(grammar, 1), grammar);
    EXPECT_EQ(graph.objects.size(), 4u);
    expectSamePlant(flatten(graph), turtlePlant(grammar, 1));
}

// The approximation: every cell shares more, and the plant moves by no more
// than docs/INSTANCING.md's bound.
TEST(InstanceGraphTropism, GranularityTradesObjectsForABoundedError) {
    const Grammar grammar = parseOk("angle: 30\nAxiom: @Ts(0.2)A\nA --> F[+A][-/(90)A]FA\n");
    const int steps = 5;
    const PlantAsset expected = turtlePlant(grammar, steps);
    const BGrammar bgrammar = interpretedBGrammar(grammar, steps);
    size_t previousObjects = 0;
    for (int granularity : {4, 8, 16, 32, 64, 128, 0}) {
        SCOPED_TRACE(granularity);
        InstanceGraphOptions options;
        options.orientationGranularity = granularity;
        const InstanceGraph graph = buildInstanceGraph(bgrammar, grammar, options);
        const PlantAsset flat = flatten(graph);
        ASSERT_EQ(flat.primitives.size(), expected.primitives.size());
        const double error = largestPositionError(flat, expected);
        const InstanceGraphStats stats = instanceGraphStats(graph);
        std::printf("G %4d: objects %5zu instances %6llu compression %6.2f largest error %.2e of the plant's size\n",
                    granularity, stats.objects, static_cast<unsigned long long>(stats.instances), stats.compression(),
                    error);
        EXPECT_GE(stats.objects, previousObjects);
        previousObjects = stats.objects;
        if (granularity == 0)
            EXPECT_LE(error, 1e-4);
        else
            EXPECT_LE(error, 2.0 * M_PI / granularity * steps);
    }
}

// Tropism vectors of any finite value key without failing, and bend the
// plant without leaving the float range (|H x T| of T = 1e30 squared past it:
// a NaN frame).
TEST(InstanceGraphTropism, DegenerateTropismVectorsStillFlatten) {
    for (const char* vector : {"0,0,0", "1e30,0,0"}) {
        SCOPED_TRACE(vector);
        const Grammar grammar = parseOk(std::string("Axiom: @Ts(0.3)@Tv(") + vector + ")A\nA --> F[+A]F[&A]\n");
        for (int granularity : {0, 16}) {
            InstanceGraphOptions options;
            options.orientationGranularity = granularity;
            const InstanceGraph graph = graphOf(grammar, 3, options);
            EXPECT_EQ(flatten(graph).primitives.size(), turtlePlant(grammar, 3).primitives.size());
        }
        for (const Primitive& primitive : turtlePlant(grammar, 3).primitives) {
            const Frame& frame = primitive.frame;
            EXPECT_TRUE(std::isfinite(frame.position.x) && std::isfinite(frame.position.y) &&
                        std::isfinite(frame.position.z) && std::isfinite(frame.rotation.w));
        }
    }
}

// An infinite or NaN component is an error on both paths (the turtle stops at
// the command that receives it), not a plant of NaN frames.
TEST(InstanceGraphTropism, NonFiniteTropismVectorsAreAnErrorOnBothPaths) {
    for (const char* vector : {"0,1/0,0", "0,0,(0/0)"}) {
        SCOPED_TRACE(vector);
        const Grammar grammar = parseOk(std::string("Axiom: @Ts(0.3)@Tv(") + vector + ")A\nA --> F[+A]F[&A]\n");
        EXPECT_THROW(graphOf(grammar, 3, {}), DerivationError);
        EXPECT_THROW(turtlePlant(grammar, 3), DerivationError);
    }
}

} // namespace
} // namespace lsys::test
