// The field's quadtree of clusters (engine/scene/clusters.h): the cluster
// order of plants, and the tree over it: every plant in exactly one leaf,
// contiguous ranges, bounds holding every plant's sphere, deterministic.
#include "engine/scene/clusters.h"
#include "engine/scene/field_content.h"
#include "shaders/shared/lod_select.h"

#include <gtest/gtest.h>

#include <random>

namespace pf {
namespace {

const ClusterSquare kRoot{glm::vec2(-200.0f), 400.0f};

std::vector<gpu::PlantModel> models() {
    std::vector<gpu::PlantModel> m(2);
    m[0].sphere = glm::vec4(0.0f, 4.0f, 0.0f, 5.0f);
    m[1].sphere = glm::vec4(0.5f, 0.3f, -0.2f, 0.4f);
    return m;
}

// Plants in clumps (so some tiles are empty) and a few outside the square.
std::vector<PlantInstance> plants(uint32_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<PlantInstance> out(n);
    for (uint32_t i = 0; i < n; ++i) {
        const glm::vec2 clump(float(i % 5) * 70.0f - 150.0f, float(i % 3) * 90.0f - 120.0f);
        const glm::vec2 xz = i % 97 == 0 ? glm::vec2(250.0f * unit(rng) - 20.0f, -230.0f)
                                         : clump + glm::vec2(unit(rng), unit(rng)) * 60.0f;
        out[i].position = glm::vec3(xz.x, 10.0f * unit(rng), xz.y);
        out[i].rotation = 6.28f * unit(rng);
        out[i].scale = 0.5f + unit(rng);
        out[i].species = i % 2;
    }
    return out;
}

std::vector<gpu::FieldInstance> instancesOf(const std::vector<PlantInstance>& plants) {
    std::vector<gpu::FieldInstance> out;
    for (const PlantInstance& p : plants)
        out.push_back({glm::vec4(p.position, p.scale), glm::vec4(p.rotation, 0, 0, 0), glm::uvec4(p.species, 0, 0, 0)});
    return out;
}

struct Built {
    std::vector<PlantInstance> plants;
    std::vector<gpu::FieldInstance> instances;
    ClusterTree tree;
};

Built build(uint32_t n, float leafSide) {
    Built b;
    b.plants = plants(n, 7);
    sortPlantsByCluster(b.plants, kRoot);
    b.instances = instancesOf(b.plants);
    b.tree = buildClusterTree(b.instances, models(), kRoot, leafSide);
    return b;
}

TEST(ClustersTest, DepthGivesTilesNoLargerThanTheLeafSide) {
    EXPECT_EQ(clusterDepthFor(kRoot, 32.0f), 4u); // 25 m tiles
    EXPECT_EQ(clusterDepthFor(kRoot, 25.0f), 4u);
    EXPECT_EQ(clusterDepthFor(kRoot, 400.0f), 0u);
    EXPECT_EQ(clusterDepthFor(kRoot, 1e-6f), kClusterOrderDepth);
}

TEST(ClustersTest, EveryPlantInExactlyOneLeafWhoseSquareHoldsIt) {
    for (float leafSide : {32.0f, 10.0f, 400.0f}) {
        const Built b = build(5000, leafSide);
        const ClusterTree& t = b.tree;
        ASSERT_GT(t.leafCount(), 0u);
        uint32_t next = 0;
        for (uint32_t l = 0; l < t.leafCount(); ++l) {
            const gpu::ClusterNode& leaf = t.nodes[l];
            EXPECT_EQ(leaf.range.w, 0u);
            EXPECT_EQ(leaf.range.x, next) << "leaves cover the plants in order, without gaps or overlaps";
            EXPECT_GT(leaf.range.y, 0u);
            next += leaf.range.y;
            EXPECT_FLOAT_EQ(leaf.square.z, kRoot.side / float(1u << t.depth));
            for (uint32_t i = leaf.range.x; i < leaf.range.x + leaf.range.y; ++i) {
                // Clamped into the edge tiles like clusterOrderKey.
                const glm::vec2 xz = glm::clamp(glm::vec2(b.plants[i].position.x, b.plants[i].position.z), kRoot.min,
                                                kRoot.min + kRoot.side - 1e-3f);
                EXPECT_GE(xz.x, leaf.square.x - 1e-3f);
                EXPECT_LE(xz.x, leaf.square.x + leaf.square.z + 1e-3f);
                EXPECT_GE(xz.y, leaf.square.y - 1e-3f);
                EXPECT_LE(xz.y, leaf.square.y + leaf.square.z + 1e-3f);
            }
        }
        EXPECT_EQ(next, b.plants.size());
    }
}

TEST(ClustersTest, InnerNodesAreTheirChildrenAndTheRootHoldsAll) {
    const Built b = build(5000, 10.0f);
    const ClusterTree& t = b.tree;
    ASSERT_EQ(t.levelStart.back() - t.levelStart[t.levels() - 1], 1u) << "one root";
    const gpu::ClusterNode& root = t.nodes.back();
    EXPECT_EQ(root.range, glm::uvec4(0, b.plants.size(), CLUSTER_NONE, t.levels() - 1));
    EXPECT_FLOAT_EQ(root.square.z, kRoot.side);
    for (uint32_t n = t.leafCount(); n < t.nodes.size(); ++n) {
        const gpu::ClusterNode& node = t.nodes[n];
        uint32_t plants = 0, next = node.range.x;
        for (uint32_t q = 0; q < 4; ++q) {
            if (node.children[q] == CLUSTER_NONE) continue;
            const gpu::ClusterNode& child = t.nodes[node.children[q]];
            EXPECT_EQ(child.range.z, n);
            EXPECT_EQ(child.range.w + 1, node.range.w);
            EXPECT_EQ(child.range.x, next) << "children in quadrant order are contiguous";
            next += child.range.y;
            plants += child.range.y;
            EXPECT_FLOAT_EQ(child.square.z * 2.0f, node.square.z);
            EXPECT_FLOAT_EQ(child.square.x, node.square.x + float(q & 1u) * child.square.z);
            EXPECT_FLOAT_EQ(child.square.y, node.square.y + float(q >> 1) * child.square.z);
            EXPECT_TRUE(glm::all(glm::lessThanEqual(node.boxMin, child.boxMin)));
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(node.boxMax, child.boxMax)));
        }
        EXPECT_EQ(plants, node.range.y);
    }
}

TEST(ClustersTest, BoundsHoldEveryPlantsSphere) {
    const Built b = build(3000, 32.0f);
    const std::vector<gpu::PlantModel> m = models();
    for (const gpu::ClusterNode& node : b.tree.nodes)
        for (uint32_t i = node.range.x; i < node.range.x + node.range.y; ++i) {
            const glm::vec4 s = gpu::instanceSphere(b.instances[i], m[b.instances[i].ids.x]);
            EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::vec3(node.boxMin), glm::vec3(s) - s.w)));
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(glm::vec3(node.boxMax), glm::vec3(s) + s.w)));
        }
}

TEST(ClustersTest, OrderIsStableAndDeterministic) {
    const Built a = build(4000, 32.0f), b = build(4000, 32.0f);
    ASSERT_EQ(a.plants.size(), b.plants.size());
    for (size_t i = 0; i < a.plants.size(); ++i) ASSERT_EQ(a.plants[i].position, b.plants[i].position);
    ASSERT_EQ(a.tree.nodes.size(), b.tree.nodes.size());
    for (size_t n = 0; n < a.tree.nodes.size(); ++n) {
        EXPECT_EQ(a.tree.nodes[n].range, b.tree.nodes[n].range);
        EXPECT_EQ(a.tree.nodes[n].boxMin, b.tree.nodes[n].boxMin);
    }
    // Two plants in one fine tile keep their order.
    std::vector<PlantInstance> twins(2);
    twins[0].position = glm::vec3(1.0f, 0.0f, 1.0f);
    twins[1].position = twins[0].position;
    twins[0].species = 5;
    twins[1].species = 3;
    sortPlantsByCluster(twins, kRoot);
    EXPECT_EQ(twins[0].species, 5u);
}

TEST(ClustersTest, UnsortedInstancesAreRejected) {
    std::vector<PlantInstance> p = plants(200, 3);
    sortPlantsByCluster(p, kRoot);
    std::swap(p.front(), p.back());
    EXPECT_THROW(buildClusterTree(instancesOf(p), models(), kRoot, 32.0f), std::runtime_error);
}

TEST(ClustersTest, FieldContentIsInClusterOrder) {
    const FieldContent content =
        buildFieldContent(loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_small.json"));
    const ClusterSquare root = clusterRoot(content.terrain);
    ASSERT_GT(content.plants.size(), 1u);
    for (size_t i = 1; i < content.plants.size(); ++i) {
        const glm::vec3 a = content.plants[i - 1].position, b = content.plants[i].position;
        EXPECT_LE(clusterOrderKey(root, {a.x, a.z}), clusterOrderKey(root, {b.x, b.z}));
    }
}

} // namespace
} // namespace pf
