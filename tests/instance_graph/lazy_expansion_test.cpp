// A lazy graph (Robbins 1998, §3): every object interpreted again from its
// entry is the object buildInstanceGraph stores, item by item and bit for
// bit, its primitives numbered alike, on every plant file and with
// orientation cells (whose keys share objects between unequal entries).

#include <gtest/gtest.h>

#include <span>
#include <string>

#include "instance_graph_test_support.h"
#include "lsystem/instancing/instance_graph_lazy.h"

namespace lsys::test {
namespace {

// Every object's expansion is the whole graph's object: its items in order,
// its primitives (numbered alike), its instances.
void expectExpansionsAreTheObjects(const InstanceGraph& whole, const LazyInstanceGraph& lazy) {
    ASSERT_EQ(lazy.graph.objects.size(), whole.objects.size());
    EXPECT_EQ(lazy.graph.root, whole.root);
    EXPECT_EQ(lazy.graph.surfaceNames, whole.surfaceNames);
    for (uint32_t object = 0; object < whole.objects.size(); ++object) {
        const GraphObject& lazyObject = lazy.graph.objects[object];
        EXPECT_EQ(lazyObject.node, whole.objects[object].node);
        EXPECT_EQ(lazyObject.bounds.min, whole.objects[object].bounds.min);
        EXPECT_EQ(lazyObject.bounds.max, whole.objects[object].bounds.max);
        EXPECT_EQ(lazyObject.primitives, whole.objects[object].primitives);
        EXPECT_EQ(lazyObject.itemCount, 0u);
        const ObjectExpansion expansion = expandObject(lazy, object);
        const std::span<const GraphItem> items = whole.itemsOf(object);
        ASSERT_EQ(expansion.items.size(), items.size()) << "object " << object;
        for (size_t i = 0; i < items.size(); ++i) {
            ASSERT_EQ(expansion.items[i].kind, items[i].kind);
            if (items[i].kind == GraphItem::Kind::Instance) {
                const GraphInstance& actual = expansion.instances[expansion.items[i].index];
                const GraphInstance& expected = whole.instances[items[i].index];
                EXPECT_EQ(actual.object, expected.object);
                EXPECT_EQ(actual.frame, expected.frame);
                EXPECT_EQ(actual.entryJoint, expected.entryJoint);
                continue;
            }
            ASSERT_EQ(expansion.primitiveIds[expansion.items[i].index], items[i].index);
            const GraphPrimitive& actual = expansion.primitives[expansion.items[i].index];
            const GraphPrimitive& expected = whole.primitives[items[i].index];
            EXPECT_EQ(actual.frame, expected.frame);
            EXPECT_EQ(actual.kind, expected.kind);
            EXPECT_EQ(actual.material, expected.material);
            EXPECT_EQ(actual.length, expected.length);
            EXPECT_EQ(actual.startRadius, expected.startRadius);
            EXPECT_EQ(actual.endRadius, expected.endRadius);
            EXPECT_EQ(actual.joint, expected.joint);
            EXPECT_EQ(actual.parentJoint, expected.parentJoint);
            if (actual.kind == PrimitiveKind::Polygon)
                EXPECT_EQ(expansion.polygons[actual.shape].outline, whole.polygons[expected.shape].outline);
            else
                EXPECT_EQ(actual.shape, expected.shape);
        }
    }
}

void expectLazyIsWhole(const Grammar& grammar, std::optional<int> steps = std::nullopt,
                       const InstanceGraphOptions& options = {}) {
    const BGrammar bgrammar = interpretedBGrammar(grammar, steps);
    const InstanceGraph whole = buildInstanceGraph(bgrammar, grammar, options);
    const LazyInstanceGraph lazy = deriveLazyInstanceGraph(bgrammar, grammar, options);
    EXPECT_TRUE(lazy.graph.items.empty() && lazy.graph.primitives.empty() && lazy.graph.instances.empty());
    expectExpansionsAreTheObjects(whole, lazy);
}

TEST(LazyInstanceGraph, EveryPlantFileExpandsToItsObjects) {
    for (const std::string& file : allPlantFiles()) {
        SCOPED_TRACE(file);
        expectLazyIsWhole(loadOk(file));
    }
}

TEST(LazyInstanceGraph, OrientationCellsExpandToTheirObjects) {
    const Grammar grammar = parseOk("angle: 30\nAxiom: @Ts(0.2)A\nA --> F[+A][-/(90)A]FA\n");
    for (int granularity : {4, 16, 128, 0}) {
        SCOPED_TRACE(granularity);
        InstanceGraphOptions options;
        options.orientationGranularity = granularity;
        expectLazyIsWhole(grammar, 5, options);
    }
}

} // namespace
} // namespace lsys::test
