// Flattening the InstanceGraph gives the turtle's plant: for every plant file
// and for grammars built to reach every turtle command across instance
// boundaries (styles, tropism, `$`, polygons, surfaces, cuts).

#include <chrono>
#include <cstdio>

#include "instance_graph_test_support.h"

namespace lsys::test {
namespace {

void expectFlattensToTurtle(const Grammar& grammar, std::optional<int> steps = std::nullopt) {
    const InstanceGraph graph = graphOf(grammar, steps);
    const PlantAsset flat = flatten(graph);
    const PlantAsset expected = turtlePlant(grammar, steps);
    expectSamePlant(flat, expected);
    const InstanceGraphStats stats = instanceGraphStats(graph);
    EXPECT_EQ(stats.primitives, expected.primitives.size());
    EXPECT_EQ(stats.joints, expected.joints.size());
}

TEST(InstanceGraphEquivalence, EveryPlantFileFlattensToTheTurtlesPlant) {
    for (const std::string& file : allPlantFiles()) {
        SCOPED_TRACE(file);
        const Grammar grammar = loadOk(file);
        const auto start = std::chrono::steady_clock::now();
        const InstanceGraph graph = graphOf(grammar);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const PlantAsset flat = flatten(graph);
        const PlantAsset expected = turtlePlant(grammar);
        expectSamePlant(flat, expected);
        const InstanceGraphStats stats = instanceGraphStats(graph);
        EXPECT_EQ(stats.primitives, expected.primitives.size());
        std::printf(
            "%-40s nodes %6zu objects %6zu instances %8llu primitives %9llu compression %8.2f error %.2e  %.4fs\n",
            file.c_str(), stats.nodes, stats.objects, static_cast<unsigned long long>(stats.instances),
            static_cast<unsigned long long>(stats.primitives), stats.compression(),
            largestPositionError(flat, expected), seconds);
    }
}

TEST(InstanceGraphEquivalence, FewerStepsOfEveryPlantFile) {
    for (const std::string& file : allPlantFiles()) {
        SCOPED_TRACE(file);
        const Grammar grammar = loadOk(file);
        for (int steps = 0; steps <= std::min(grammar.derivationLength, 4); ++steps) {
            SCOPED_TRACE(steps);
            expectFlattensToTurtle(grammar, steps);
        }
    }
}

// Deeper graphs compose more transforms: the 6-step bush (262 144 segments,
// instances 6 levels deep) stays within the tolerance.
TEST(InstanceGraphEquivalence, DeepBush) { expectFlattensToTurtle(loadOk("plants/fractal_bush.lsys"), 6); }

// Every style field is set, scaled or read on one side of an instance
// boundary and used on the other.
TEST(InstanceGraphEquivalence, StylesCrossInstanceBoundaries) {
    const char* sources[] = {
        "Axiom: A\nA --> F!A[+!(0.5)A]@Wm(0.8)F-A\n",
        "Axiom: A(3)\nA(n) : n > 0 --> ;F[+A(n-1)]'A(n-1)@Ca(2)F\n",
        "Axiom: A(3)\nA(n) : n > 0 --> @Lm(1.5)F[&A(n-1)]f@La(0.25)A(n-1)@Ls(2)F\n",
        "Axiom: A(3)\nA(n) : n > 0 --> +@Am(0.5)[+A(n-1)]@Aa(10)-A(n-1)@As(30)^F\n",
        "Axiom: A(3)\nA(n) : n > 0 --> @K(n)F[\\(30)A(n-1)]@K F(2,0.5)/A(n-1)|F\n",
        "Axiom: A(3)\nA(n) : n > 0 --> F(1,n)[+A(n-1)@O]@O(0.5)A(n-1)~leaf(0.5)\n",
        "Axiom: A\nA --> F[+A]F[-A[F]A]F\nF --> FF\n",
        "Axiom: A\nA --> F[[+A]-A\n",                                // leaves states pushed: Fig 4.5's g functions
        "Axiom: A(4)]]]]F\nA(n) : n > 0 --> F[+A(n-1)]F\n",          // the axiom pops below the start: ignored
        "Axiom: A(3)F\nA(n) : n > 0 --> F[+A(n-1)%F]F[-A(n-1)F]F\n", // % in the word (the axiom's)
        "Axiom: A(3)\nA(n) : n > 0 --> F[+A(n-1)]F[-A(n-1)]F\ninterpretation:\nF --> F[%]F\n",
    };
    for (const char* source : sources) {
        SCOPED_TRACE(source);
        expectFlattensToTurtle(parseOk(source), 4);
    }
}

TEST(InstanceGraphEquivalence, OrientationDependentCommands) {
    const char* sources[] = {
        "Axiom: @Ts(0.3)A\nA --> F[+A]F[&A]/(40)F\n",      // tropism, entered at any orientation
        "Axiom: A\nA --> F[+@Ts(0.2)A]@Tv(1,0,0)F[^A]F\n", // @Tv sets a world vector
        "Axiom: &(60)A\nA --> F[+$A]F[&(30)$A]/(40)F\n",   // $ levels against the world's vertical
        "Axiom: A\nA --> @Ts(-0.4)F[+(30)A]@Tv(0,0,-1)F[-(30)A]@Ts(0)F\n",
        "Axiom: @Ts(0.3)A\nA --> F[+A]@Tv(1,0)F[-A]@Tv F\n", // @Tv without three parameters changes nothing
        // cpfg's bend, toward U then toward L (a cpfg file's turtle)
        "turtle modules: cpfg\nAxiom: @Ts(0.3)@Tv(1,0,1)A\nA --> F[+A]F[&A]/(40)F\n",
    };
    for (const char* source : sources) {
        SCOPED_TRACE(source);
        expectFlattensToTurtle(parseOk(source), 4);
    }
}

// cpfg's @M and @R place the turtle in plant space, wherever the instance
// holding them stands: the root interprets the whole word, one object.
TEST(InstanceGraphEquivalence, PlantSpaceCommandsMakeOneObject) {
    const char* sources[] = {
        "turtle modules: cpfg\nAxiom: A(1)\nA(n) --> F[+A(n+1)]F[-@M(n,2*n)A(n+1)]/(40)F\n",
        "turtle modules: cpfg\nAxiom: A\nA --> F[+A]F[-@R(1,1,0)A]F[@R(0,1,1,1,0,0)A]F\n",
    };
    for (const char* source : sources) {
        SCOPED_TRACE(source);
        const Grammar grammar = parseOk(source);
        expectFlattensToTurtle(grammar, 3);
        EXPECT_EQ(graphOf(grammar, 3).objects.size(), 1u);
    }
}

TEST(InstanceGraphEquivalence, PolygonsAcrossInstances) {
    const char* sources[] = {
        "Axiom: A\nA --> F[+A]{.-f.+f.}F[-A]\n",                               // inside one object
        "Axiom: A(3)\nA(n) : n > 0 --> F[{.E+E-E}]A(n-1)\nE --> f.F\n",        // vertices from instances
        "Axiom: A(3)\nA(n) : n > 0 --> F[B+A(n-1)C]\nB --> {.f.\nC --> f.}\n", // opened in one node, closed in another
        "Axiom: {.A(3)}\nA(n) : n > 0 --> f.F[+A(n-1)]\n",                     // F inside a polygon opened by the axiom
    };
    for (const char* source : sources) {
        SCOPED_TRACE(source);
        expectFlattensToTurtle(parseOk(source), 3);
    }
}

// Every object's box holds what its subtree draws, so the root's holds the plant.
TEST(InstanceGraphBounds, ObjectBoundsContainTheirPrimitives) {
    for (const std::string& file : allPlantFiles()) {
        SCOPED_TRACE(file);
        const Grammar grammar = loadOk(file);
        const InstanceGraph graph = graphOf(grammar);
        const PlantAsset flat = flatten(graph);
        const Bounds& root = graph.objects[graph.root].bounds;
        if (flat.bounds.empty()) continue;
        const glm::vec3 slack(1e-4f * static_cast<float>(plantSize(flat)));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(root.min, flat.bounds.min + slack)));
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(root.max, flat.bounds.max - slack)));
        for (size_t i = 0; i < graph.objects.size(); ++i) {
            const GraphObject& object = graph.objects[i];
            EXPECT_EQ(object.bounds.empty(), object.primitives == 0) << "object " << i;
        }
    }
}

} // namespace
} // namespace lsys::test
