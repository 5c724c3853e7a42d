// Packing a GraphTracer for the GPU traversal (engine/raytrace/gpu_graph.h):
// every object's BVH with global indices, frames and triangles as the tracer
// holds them, and graphs the traversal's fixed arrays cannot hold refused.

#include "../instance_graph/instance_graph_test_support.h"
#include "chain_graph.h"
#include "engine/raytrace/gpu_graph.h"

#include <gtest/gtest.h>

#include <string>

namespace pf::test {
namespace {

using lsys::GraphItem;
using lsys::InstanceGraph;

TEST(GpuGraph, HoldsEveryObjectsBvhWithGlobalIndices) {
    const InstanceGraph graph = lsys::test::graphOf(lsys::test::loadOk("plants/broadleaf.lsys"));
    const lsys::GraphTracer tracer = lsys::buildGraphTracer(graph);
    const GpuGraph packed = packGraph(tracer);
    ASSERT_EQ(packed.objectRoots.size(), graph.objects.size());
    size_t nodes = 0;
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        const lsys::Bvh& bvh = tracer.objectBvhs[object];
        if (bvh.nodes.empty()) {
            EXPECT_EQ(packed.objectRoots[object], RAYTRACE_NO_NODE);
            continue;
        }
        const uint32_t root = packed.objectRoots[object];
        EXPECT_EQ(root, nodes);
        nodes += bvh.nodes.size();
        for (size_t n = 0; n < bvh.nodes.size(); ++n) {
            const gpu::RtNode& node = packed.nodes[root + n];
            EXPECT_EQ(node.boundsMin, bvh.nodes[n].bounds.min);
            EXPECT_EQ(node.boundsMax, bvh.nodes[n].bounds.max);
            ASSERT_EQ(node.count, bvh.nodes[n].count);
            if (node.count == 0) {
                EXPECT_EQ(node.first, root + bvh.nodes[n].first);
                continue;
            }
            for (uint32_t i = 0; i < node.count; ++i) {
                const GraphItem& item = graph.itemsOf(object)[bvh.items[bvh.nodes[n].first + i]];
                const uint32_t expected =
                    item.kind == GraphItem::Kind::Instance ? RAYTRACE_ITEM_INSTANCE | item.index : item.index;
                EXPECT_EQ(packed.items[node.first + i], expected);
            }
        }
    }
    EXPECT_EQ(packed.nodes.size(), nodes);
    EXPECT_EQ(packed.rootNode, packed.objectRoots[graph.root]);

    ASSERT_EQ(packed.primitives.size(), tracer.primitives.size());
    size_t surfaces = 0;
    for (size_t i = 0; i < packed.primitives.size(); ++i) {
        const gpu::RtPrimitive& p = packed.primitives[i];
        const lsys::Primitive& expected = tracer.primitives[i];
        EXPECT_EQ(p.position, expected.frame.position);
        EXPECT_EQ(p.rotation, glm::vec4(expected.frame.rotation.x, expected.frame.rotation.y, expected.frame.rotation.z,
                                        expected.frame.rotation.w));
        EXPECT_EQ(p.kind, uint32_t(expected.kind));
        EXPECT_EQ(p.extent, expected.length);
        if (expected.kind != lsys::PrimitiveKind::Surface) continue;
        ++surfaces;
        const lsys::TriangleMesh& mesh = tracer.shapes.surfaces.meshes[expected.shape];
        ASSERT_EQ(p.triangleCount, mesh.triangleCount());
        EXPECT_EQ(glm::vec3(packed.triangles[p.firstTriangle].b), mesh.positions[mesh.indices[1]]);
    }
    EXPECT_GT(surfaces, 0u);
    for (size_t i = 0; i < graph.instances.size(); ++i) {
        EXPECT_EQ(packed.instances[i].object, graph.instances[i].object);
        EXPECT_EQ(packed.instances[i].position, graph.instances[i].frame.position);
    }
    EXPECT_GE(packed.levels, 2u);
    EXPECT_LE(packed.levels, uint32_t(RAYTRACE_MAX_LEVELS));
    EXPECT_LE(packed.stackDepth, uint32_t(RAYTRACE_STACK_SIZE));
}

TEST(GpuGraph, CountsTheInstanceLevelsARayCanCross) {
    const InstanceGraph graph = chainGraph(RAYTRACE_MAX_LEVELS, 1);
    EXPECT_EQ(packGraph(lsys::buildGraphTracer(graph)).levels, uint32_t(RAYTRACE_MAX_LEVELS));
}

TEST(GpuGraph, RefusesMoreInstanceLevelsThanTheTraversalHolds) {
    const InstanceGraph graph = chainGraph(RAYTRACE_MAX_LEVELS + 1, 1);
    try {
        packGraph(lsys::buildGraphTracer(graph));
        FAIL() << "a graph of " << RAYTRACE_MAX_LEVELS + 1 << " levels was packed";
    } catch (const GpuGraphError& error) {
        EXPECT_NE(std::string(error.what()).find("RAYTRACE_MAX_LEVELS"), std::string::npos) << error.what();
    }
}

// 64 segments and an instance make a BVH of height 6 (leaves of 4) in every
// object: 14 levels of them can need more than 96 stack entries.
TEST(GpuGraph, RefusesAGraphNeedingADeeperStack) {
    const InstanceGraph graph = chainGraph(14, 64);
    try {
        const GpuGraph packed = packGraph(lsys::buildGraphTracer(graph));
        FAIL() << "packed with a stack of " << packed.stackDepth;
    } catch (const GpuGraphError& error) {
        EXPECT_NE(std::string(error.what()).find("RAYTRACE_STACK_SIZE"), std::string::npos) << error.what();
    }
}

} // namespace
} // namespace pf::test
