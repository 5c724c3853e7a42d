#pragma once
// A bounding volume hierarchy over a list of boxes (docs/RAYTRACING.md, "The
// BVH"), and its traversal near to far. It knows nothing of what the boxes
// bound: the flat tracer builds one over a plant's primitives, the graph
// tracer one per object over its items.

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "lsystem/raytrace/intersect.h"
#include "lsystem/raytrace/ray.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys {

struct BvhNode {
    Bounds bounds;
    uint32_t first = 0; // leaf: into Bvh::items; inner: its first child (the second follows it)
    uint32_t count = 0; // leaf: its items; 0 for an inner node
};

struct Bvh {
    std::vector<BvhNode> nodes;  // nodes[0] is the root; none when nothing has a box
    std::vector<uint32_t> items; // indices into the boxes it was built over, leaf by leaf
};

// At most this many items in a leaf, by default.
inline constexpr uint32_t kBvhLeafSize = 4;

// Splits each node at the median of its boxes' centres along the longest
// axis of those centres, down to leaves of at most `leafSize` items (or of
// items whose centres coincide). Empty boxes are left out (nothing to hit).
// Deterministic: the same boxes give the same tree.
Bvh buildBvh(std::span<const Bounds> boxes, uint32_t leafSize = kBvhLeafSize);

// Visits the items whose boxes the ray meets, nearer boxes first, skipping
// boxes that begin past ray.tMax. `visit(item)` tests the item, lowering
// ray.tMax when it finds a hit, and returns true to end the walk (an any-hit
// query's first hit).
template <typename Visit>
void traverseBvh(const Bvh& bvh, const Ray& ray, Visit&& visit) {
    if (bvh.nodes.empty()) return;
    // Median splits keep the depth at log2 of the items: 64 levels are plenty.
    // Left uninitialised: the graph tracer walks a BVH per instance a ray
    // enters, and zeroing 64 entries each time would cost more than the walk.
    struct Pending {
        uint32_t node;
        float entry;
    };
    Pending stack[64];
    size_t size = 0;
    const BoxRay boxRay = boxRayOf(ray); // its origin and direction stay; visit lowers tMax
    if (std::optional<float> entry = boxEntry(boxRay, bvh.nodes[0].bounds, ray.tMax)) stack[size++] = {0, *entry};
    while (size > 0) {
        const auto [index, entry] = stack[--size];
        if (entry > ray.tMax) continue; // a nearer hit was found since it was pushed
        const BvhNode& node = bvh.nodes[index];
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i)
                if (visit(bvh.items[i])) return;
            continue;
        }
        std::optional<float> near = boxEntry(boxRay, bvh.nodes[node.first].bounds, ray.tMax);
        std::optional<float> far = boxEntry(boxRay, bvh.nodes[node.first + 1].bounds, ray.tMax);
        uint32_t nearIndex = node.first, farIndex = node.first + 1;
        if (!near || (far && *far < *near)) {
            std::swap(near, far);
            std::swap(nearIndex, farIndex);
        }
        if (far) stack[size++] = {farIndex, *far};
        if (near) stack[size++] = {nearIndex, *near};
    }
}

} // namespace lsys
