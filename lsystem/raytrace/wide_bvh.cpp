#include "lsystem/raytrace/wide_bvh.h"

namespace lsys {
namespace {

float surfaceArea(const Bounds& box) {
    const glm::vec3 size = box.max - box.min;
    return size.x * size.y + size.y * size.z + size.z * size.x;
}

// The lanes of a wide node standing for the binary node `binary`: it is
// opened into its children, and the inner lane of largest surface area
// likewise, until four lanes are full or only leaves are left. A leaf stays
// one lane. The lanes keep the binary tree's order.
uint32_t openLanes(const Bvh& bvh, uint32_t binary, uint32_t (&lanes)[kWideBvhLanes]) {
    lanes[0] = binary;
    uint32_t count = 1;
    while (count < kWideBvhLanes) {
        int largest = -1;
        for (uint32_t lane = 0; lane < count; ++lane)
            if (bvh.nodes[lanes[lane]].count == 0 && (largest < 0 || surfaceArea(bvh.nodes[lanes[lane]].bounds) >
                                                                         surfaceArea(bvh.nodes[lanes[largest]].bounds)))
                largest = int(lane);
        if (largest < 0) break;
        const BvhNode& opened = bvh.nodes[lanes[largest]];
        for (uint32_t lane = count; lane > uint32_t(largest) + 1; --lane) lanes[lane] = lanes[lane - 1];
        lanes[largest] = opened.first;
        lanes[largest + 1] = opened.first + 1;
        ++count;
    }
    return count;
}

// Fills wide.nodes[index] for the binary node `binary`, then the nodes of
// its inner lanes after it, depth first.
void widenNode(const Bvh& bvh, uint32_t binary, WideBvh& wide, uint32_t index) {
    uint32_t lanes[kWideBvhLanes];
    const uint32_t count = openLanes(bvh, binary, lanes);
    WideBvhNode node;
    for (uint32_t lane = 0; lane < kWideBvhLanes; ++lane) {
        const BvhNode* source = lane < count ? &bvh.nodes[lanes[lane]] : nullptr;
        for (int axis = 0; axis < 3; ++axis) {
            node.planes[2 * axis][lane] = source ? source->bounds.min[axis] : 0.0f;
            node.planes[2 * axis + 1][lane] = source ? source->bounds.max[axis] : 0.0f;
        }
        node.first[lane] = source ? source->first : 0;
        node.count[lane] = source ? source->count : kEmptyLane;
    }
    for (uint32_t lane = 0; lane < count; ++lane) {
        if (node.count[lane] > 0) continue;
        node.first[lane] = uint32_t(wide.nodes.size());
        wide.nodes.emplace_back();
        widenNode(bvh, lanes[lane], wide, node.first[lane]);
    }
    wide.nodes[index] = node;
}

} // namespace

WideBvh widen(const Bvh& bvh) {
    WideBvh wide;
    if (bvh.nodes.empty()) return wide;
    wide.items = bvh.items;
    wide.nodes.emplace_back();
    widenNode(bvh, 0, wide, 0);
    return wide;
}

} // namespace lsys
