// The BVH's structure over random boxes, and its traversal against testing
// every box.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "lsystem/raytrace/bvh.h"

namespace lsys {
namespace {

std::vector<Bounds> randomBoxes(size_t count, uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> position(-10.0f, 10.0f), size(0.01f, 1.0f);
    std::vector<Bounds> boxes;
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 min(position(random), position(random), position(random));
        boxes.push_back({min, min + glm::vec3(size(random), size(random), size(random))});
    }
    return boxes;
}

bool contains(const Bounds& outer, const Bounds& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
}

TEST(Bvh, EveryBoxIsInOneLeafInsideEveryNodeAboveIt) {
    std::vector<Bounds> boxes = randomBoxes(1000, 1);
    boxes[17] = Bounds{}; // nothing to hit: left out
    const Bvh bvh = buildBvh(boxes);
    std::vector<int> seen(boxes.size(), 0);
    // Walk down from the root, checking containment.
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
        const BvhNode& node = bvh.nodes[stack.back()];
        stack.pop_back();
        if (node.count > 0) {
            EXPECT_LE(node.count, kBvhLeafSize);
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                ++seen[bvh.items[i]];
                EXPECT_TRUE(contains(node.bounds, boxes[bvh.items[i]]));
            }
            continue;
        }
        for (uint32_t child : {node.first, node.first + 1}) {
            EXPECT_TRUE(contains(node.bounds, bvh.nodes[child].bounds));
            stack.push_back(child);
        }
    }
    for (size_t i = 0; i < boxes.size(); ++i) EXPECT_EQ(seen[i], i == 17 ? 0 : 1) << "box " << i;
}

TEST(Bvh, NothingToHitGivesNoNodes) {
    EXPECT_TRUE(buildBvh(std::vector<Bounds>{}).nodes.empty());
    EXPECT_TRUE(buildBvh(std::vector<Bounds>(3)).nodes.empty());
    Ray ray;
    traverseBvh(Bvh{}, ray, [](uint32_t) {
        ADD_FAILURE() << "visited an item of an empty tree";
        return false;
    });
}

TEST(Bvh, TraversalVisitsExactlyTheBoxesTheRayMeets) {
    const std::vector<Bounds> boxes = randomBoxes(2000, 2);
    const Bvh bvh = buildBvh(boxes);
    std::mt19937 random(3);
    std::uniform_real_distribution<float> coordinate(-12.0f, 12.0f);
    size_t visits = 0;
    for (int r = 0; r < 200; ++r) {
        const glm::vec3 origin(coordinate(random), coordinate(random), coordinate(random));
        const glm::vec3 target(coordinate(random), coordinate(random), coordinate(random));
        const Ray ray{origin, target - origin};
        std::vector<uint32_t> expected, visited;
        for (uint32_t i = 0; i < boxes.size(); ++i)
            if (boxEntry(ray, boxes[i])) expected.push_back(i);
        traverseBvh(bvh, ray, [&](uint32_t item) {
            if (boxEntry(ray, boxes[item])) visited.push_back(item);
            return false;
        });
        std::sort(visited.begin(), visited.end());
        EXPECT_EQ(visited, expected) << "ray " << r;
        visits += visited.size();
    }
    EXPECT_GT(visits, 200u); // the rays do cross boxes
}

TEST(Bvh, VisitsNearerBoxesFirstAndStopsWhenAsked) {
    // A row of unit boxes along +X; a ray down the row from the left.
    std::vector<Bounds> boxes;
    for (int i = 0; i < 64; ++i) boxes.push_back({glm::vec3(float(i), 0, 0), glm::vec3(float(i) + 0.5f, 1, 1)});
    std::reverse(boxes.begin(), boxes.end());
    const Bvh bvh = buildBvh(boxes);
    const Ray ray{glm::vec3(-1, 0.5f, 0.5f), glm::vec3(1, 0, 0)};
    std::vector<uint32_t> order;
    traverseBvh(bvh, ray, [&](uint32_t item) {
        order.push_back(item);
        return order.size() == 10;
    });
    ASSERT_EQ(order.size(), 10u);
    // The first leaf reached holds the nearest box (index 63 after the reversal).
    EXPECT_NE(std::find(order.begin(), order.begin() + kBvhLeafSize, 63u), order.begin() + kBvhLeafSize);
    for (uint32_t item : order) EXPECT_GE(item, 64u - 16u) << "a far box before the near ones";
}

TEST(Bvh, SameBoxesSameTree) {
    const std::vector<Bounds> boxes = randomBoxes(500, 4);
    const Bvh a = buildBvh(boxes), b = buildBvh(boxes);
    EXPECT_EQ(a.items, b.items);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_EQ(a.nodes[i].first, b.nodes[i].first);
        EXPECT_EQ(a.nodes[i].count, b.nodes[i].count);
    }
}

} // namespace
} // namespace lsys
