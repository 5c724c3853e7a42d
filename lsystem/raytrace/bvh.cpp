#include "lsystem/raytrace/bvh.h"

#include <algorithm>

namespace lsys {
namespace {

glm::vec3 centreOf(const Bounds& box) { return 0.5f * (box.min + box.max); }

// Fills nodes[index] with the subtree over items[first, first + count).
void buildNode(Bvh& bvh, std::span<const Bounds> boxes, uint32_t leafSize, uint32_t index, uint32_t first,
               uint32_t count) {
    const auto begin = bvh.items.begin() + first, end = begin + count;
    Bounds bounds, centres;
    for (auto it = begin; it != end; ++it) {
        bounds.extend(boxes[*it]);
        centres.extend(centreOf(boxes[*it]));
    }
    bvh.nodes[index].bounds = bounds;
    const glm::vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    if (count <= leafSize || extent[axis] <= 0.0f) {
        bvh.nodes[index].first = first;
        bvh.nodes[index].count = count;
        return;
    }
    const uint32_t half = count / 2;
    std::nth_element(begin, begin + half, end, [&](uint32_t a, uint32_t b) {
        const float ca = centreOf(boxes[a])[axis], cb = centreOf(boxes[b])[axis];
        return ca < cb || (ca == cb && a < b); // a total order: the split does not depend on the library's ties
    });
    const auto children = uint32_t(bvh.nodes.size());
    bvh.nodes.resize(bvh.nodes.size() + 2);
    bvh.nodes[index].first = children;
    bvh.nodes[index].count = 0;
    buildNode(bvh, boxes, leafSize, children, first, half);
    buildNode(bvh, boxes, leafSize, children + 1, first + half, count - half);
}

} // namespace

Bvh buildBvh(std::span<const Bounds> boxes, uint32_t leafSize) {
    Bvh bvh;
    for (uint32_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].empty()) bvh.items.push_back(i);
    if (bvh.items.empty()) return bvh;
    bvh.nodes.resize(1);
    buildNode(bvh, boxes, std::max(leafSize, 1u), 0, 0, uint32_t(bvh.items.size()));
    return bvh;
}

} // namespace lsys
