// An object is keyed by its node and the entry values it read: entries that
// differ only in values the node overwrites, passes through or never uses
// share it; entries that differ in a value it draws with do not.

#include "instance_graph_test_support.h"

namespace lsys::test {
namespace {

// Objects built for the node the first instance of the root refers to.
size_t objectsOfFirstChild(const InstanceGraph& graph) {
    const uint32_t node = graph.objects[graph.instances.front().object].node;
    size_t count = 0;
    for (const GraphObject& object : graph.objects) count += object.node == node;
    return count;
}

size_t objectsFor(const char* source) {
    const Grammar grammar = parseOk(source);
    const InstanceGraph graph = graphOf(grammar, 1);
    expectSamePlant(flatten(graph), turtlePlant(grammar, 1));
    return objectsOfFirstChild(graph);
}

TEST(InstanceGraphKeys, ValuesOverwrittenOrPassedThroughAreNotKeys) {
    // Every entry differs in width, material, length and angle.
    const char* entries = "Axiom: !(1);(1)@Ls(1)@As(10)A!(2);(2)@Ls(2)@As(20)A!(3);(3)@Ls(3)@As(30)A\n";
    EXPECT_EQ(objectsFor((std::string(entries) + "A --> !(0.5);(4)F(1)+(5)f(1)[&(5)F(2)]\n").c_str()), 1u);
    // Scaled inside a branch and popped: never used.
    EXPECT_EQ(objectsFor((std::string(entries) + "A --> !(0.5);(4)[!;@Lm(2)@Am(2)]F(1)\n").c_str()), 1u);
    // Scaled and left to the caller: the exit is a function of the entry, which is read.
    EXPECT_EQ(objectsFor((std::string(entries) + "A --> !(0.5);(4)F(1)@Lm(2)\n").c_str()), 3u);
    EXPECT_EQ(objectsFor((std::string(entries) + "A --> @Wm(2)F(1)+(5)F(1)\n").c_str()), 3u);
    EXPECT_EQ(objectsFor((std::string(entries) + "A --> !(0.5);(4)F+(5)F\n").c_str()), 3u);    // bare F: the length
    EXPECT_EQ(objectsFor((std::string(entries) + "A --> !(0.5);(4)F(1)+F(1)\n").c_str()), 3u); // bare +: the angle
}

TEST(InstanceGraphKeys, TheEntryFrameAndJointAreNeverKeys) {
    EXPECT_EQ(objectsFor("Axiom: A+(33)fA&(12)F[A]FA\nA --> F[+F]F\n"), 1u);
}

} // namespace
} // namespace lsys::test
