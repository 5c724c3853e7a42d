// The BVH's structure over random boxes, and its traversal against testing
// every box.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "lsystem/raytrace/bvh.h"
#include "lsystem/raytrace/wide_bvh.h"

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

// Random rays through random boxes: `traverse(ray, visit)` visits every box
// the ray meets (and maybe more, which the visit tests), each once.
template <typename Traverse>
void expectVisitsExactlyTheBoxesTheRayMeets(const std::vector<Bounds>& boxes, Traverse&& traverse) {
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
        traverse(ray, [&](uint32_t item) {
            if (boxEntry(ray, boxes[item])) visited.push_back(item);
            return false;
        });
        std::sort(visited.begin(), visited.end());
        EXPECT_EQ(visited, expected) << "ray " << r;
        visits += visited.size();
    }
    EXPECT_GT(visits, 200u); // the rays do cross boxes
}

TEST(Bvh, TraversalVisitsExactlyTheBoxesTheRayMeets) {
    const std::vector<Bounds> boxes = randomBoxes(2000, 2);
    const Bvh bvh = buildBvh(boxes);
    expectVisitsExactlyTheBoxesTheRayMeets(boxes, [&](const Ray& ray, auto&& visit) { traverseBvh(bvh, ray, visit); });
}

// A row of unit boxes along +X, nearest last; `traverse(ray, visit)` from the
// left must reach the nearest leaf first and stop at the tenth item.
template <typename Traverse>
void expectNearerBoxesFirst(uint32_t leafSize, Traverse&& traverse) {
    const Ray ray{glm::vec3(-1, 0.5f, 0.5f), glm::vec3(1, 0, 0)};
    std::vector<uint32_t> order;
    traverse(ray, [&](uint32_t item) {
        order.push_back(item);
        return order.size() == 10;
    });
    ASSERT_EQ(order.size(), 10u);
    // The first leaf reached holds the nearest box (index 63 after the reversal).
    EXPECT_NE(std::find(order.begin(), order.begin() + leafSize, 63u), order.begin() + leafSize);
    for (uint32_t item : order) EXPECT_GE(item, 64u - 16u) << "a far box before the near ones";
}

std::vector<Bounds> rowOfBoxes() {
    std::vector<Bounds> boxes;
    for (int i = 0; i < 64; ++i) boxes.push_back({glm::vec3(float(i), 0, 0), glm::vec3(float(i) + 0.5f, 1, 1)});
    std::reverse(boxes.begin(), boxes.end());
    return boxes;
}

TEST(Bvh, VisitsNearerBoxesFirstAndStopsWhenAsked) {
    const Bvh bvh = buildBvh(rowOfBoxes());
    expectNearerBoxesFirst(kBvhLeafSize, [&](const Ray& ray, auto&& visit) { traverseBvh(bvh, ray, visit); });
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

// Every item in exactly one leaf lane, each lane's box inside the lanes above it.
void expectWideBvhHoldsEveryBoxOnce(const std::vector<Bounds>& boxes, const WideBvh& wide) {
    std::vector<int> seen(boxes.size(), 0);
    struct Lane {
        uint32_t node;
        Bounds bounds;
    };
    std::vector<Lane> stack{{0, Bounds{glm::vec3(-1e9f), glm::vec3(1e9f)}}};
    while (!stack.empty()) {
        const Lane above = stack.back();
        stack.pop_back();
        const WideBvhNode& node = wide.nodes[above.node];
        for (uint32_t lane = 0; lane < kWideBvhLanes; ++lane) {
            if (node.count[lane] == kEmptyLane) continue;
            const Bounds box{{node.planes[0][lane], node.planes[2][lane], node.planes[4][lane]},
                             {node.planes[1][lane], node.planes[3][lane], node.planes[5][lane]}};
            EXPECT_TRUE(contains(above.bounds, box));
            if (node.count[lane] == 0) {
                stack.push_back({node.first[lane], box});
                continue;
            }
            for (uint32_t i = node.first[lane]; i < node.first[lane] + node.count[lane]; ++i) {
                ++seen[wide.items[i]];
                EXPECT_TRUE(contains(box, boxes[wide.items[i]]));
            }
        }
    }
    for (size_t i = 0; i < boxes.size(); ++i) EXPECT_EQ(seen[i], boxes[i].empty() ? 0 : 1) << "box " << i;
}

TEST(WideBvh, EveryBoxIsInOneLeafLaneInsideEveryLaneAboveIt) {
    for (uint32_t leafSize : {1u, kBvhLeafSize}) {
        std::vector<Bounds> boxes = randomBoxes(1000, 5);
        boxes[17] = Bounds{}; // nothing to hit: left out
        expectWideBvhHoldsEveryBoxOnce(boxes, widen(buildBvh(boxes, leafSize)));
    }
    // A root that is a leaf: one lane.
    const std::vector<Bounds> few = randomBoxes(3, 6);
    expectWideBvhHoldsEveryBoxOnce(few, widen(buildBvh(few)));
}

TEST(WideBvh, NothingToHitGivesNoNodes) {
    EXPECT_TRUE(widen(Bvh{}).nodes.empty());
    Ray ray;
    traverseWideBvh(WideBvh{}, ray, [](uint32_t) {
        ADD_FAILURE() << "visited an item of an empty tree";
        return false;
    });
}

TEST(WideBvh, TraversalVisitsExactlyTheBoxesTheRayMeets) {
    const std::vector<Bounds> boxes = randomBoxes(2000, 2);
    for (uint32_t leafSize : {1u, kBvhLeafSize}) {
        const WideBvh wide = widen(buildBvh(boxes, leafSize));
        expectVisitsExactlyTheBoxesTheRayMeets(
            boxes, [&](const Ray& ray, auto&& visit) { traverseWideBvh(wide, ray, visit); });
    }
}

TEST(WideBvh, VisitsNearerBoxesFirstAndStopsWhenAsked) {
    const WideBvh wide = widen(buildBvh(rowOfBoxes(), 1));
    expectNearerBoxesFirst(1, [&](const Ray& ray, auto&& visit) { traverseWideBvh(wide, ray, visit); });
}

// A node's unused lanes are never entered, though a ray passes where their
// (zero) planes lie.
TEST(WideBvh, UnusedLanesAreNeverEntered) {
    const std::vector<Bounds> boxes{{glm::vec3(2), glm::vec3(3)}};
    const WideBvh wide = widen(buildBvh(boxes, 1)); // one lane of four used
    traverseWideBvh(wide, Ray{glm::vec3(0, 0, -1), glm::vec3(0, 0, 1)}, [](uint32_t) {
        ADD_FAILURE() << "visited an item the ray misses";
        return false;
    });
}

// A ray along a face of a box enters it, as boxEntry says (its NaN ignored).
TEST(WideBvh, ARayAlongAFaceEntersTheBox) {
    const std::vector<Bounds> boxes{{glm::vec3(0), glm::vec3(1)}, {glm::vec3(5), glm::vec3(6)}};
    const WideBvh wide = widen(buildBvh(boxes, 1));
    for (const Ray& ray :
         {Ray{glm::vec3(-1, 0, 0.5f), glm::vec3(1, 0, 0)}, Ray{glm::vec3(0.5f, 1, -1), glm::vec3(0, 0, 1)}}) {
        ASSERT_TRUE(boxEntry(ray, boxes[0]));
        size_t visits = 0;
        traverseWideBvh(wide, ray, [&](uint32_t item) {
            visits += item == 0;
            return false;
        });
        EXPECT_EQ(visits, 1u);
    }
}

} // namespace
} // namespace lsys
