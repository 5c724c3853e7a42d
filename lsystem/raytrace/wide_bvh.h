#pragma once
// A BVH of four children a node, made from a binary one for the CPU walk
// (docs/RAYTRACING.md, "The BVH"): the four children's boxes side by side,
// so one pass over them tests all four, and a walk takes half the steps.
// Wald et al., "Getting Rid of Packets" (2008), and Dammertz et al.,
// "Shallow Bounding Volume Hierarchies for Fast SIMD Ray Tracing of
// Incoherent Rays" (2008), trace single rays through such trees. The graph
// tracer walks these; the binary Bvh stays what the GPU traversal packs.

#include <cstdint>
#include <vector>

#include "lsystem/raytrace/bvh.h"
#include "lsystem/raytrace/ray.h"

namespace lsys {

inline constexpr uint32_t kWideBvhLanes = 4;
// A lane that holds nothing: never entered.
inline constexpr uint32_t kEmptyLane = UINT32_MAX;

// Four floats computed together, with GCC's and Clang's vector extension
// (SSE on x86-64, NEON on ARM, four scalars elsewhere): a node's four boxes
// tested at once.
using Float4 = float __attribute__((vector_size(4 * sizeof(float))));

struct WideBvhNode {
    Float4 planes[6];              // the lanes' boxes: min x, max x, min y, max y, min z, max z
    uint32_t first[kWideBvhLanes]; // an inner lane's node; a leaf lane's first item in WideBvh::items
    uint32_t count[kWideBvhLanes]; // a leaf lane's items; 0 for an inner lane, kEmptyLane for none
};

struct WideBvh {
    std::vector<WideBvhNode> nodes; // nodes[0] is the root; none when nothing has a box
    std::vector<uint32_t> items;    // the binary BVH's items, in its order
};

// Each node stands for a binary node: it is opened into its two children,
// and the inner lane of largest surface area likewise, until four lanes are
// full or only leaves are left (a leaf root is one lane). Leaves keep their
// items, in the binary tree's order.
WideBvh widen(const Bvh& bvh);

// The longest stack a walk needs: a median-split binary tree is at most 33
// levels deep (2^32 items), a wide node lies a binary level or more below
// its parent, and each leaves at most three lanes pending besides the one
// it enters.
inline constexpr uint32_t kWideBvhStack = 3 * 33;

// As traverseBvh: visits the items whose boxes the ray meets, nearer lanes
// first, skipping lanes that begin past ray.tMax; `visit(item)` lowers
// ray.tMax on a hit and returns true to end the walk.
template <typename Visit>
void traverseWideBvh(const WideBvh& bvh, const Ray& ray, Visit&& visit) {
    if (bvh.nodes.empty()) return;
    struct Pending {
        uint32_t first, count; // a lane: a node (count 0) or a leaf's items
        float entry;
    };
    Pending stack[kWideBvhStack]; // left uninitialised, as traverseBvh's
    size_t size = 0;
    // The slabs of Kay and Kajiya (1986) as boxEntry takes them, a lane's
    // near plane being its max where the direction is negative. A NaN (a ray
    // parallel to an axis, its origin on a face) leaves the interval as it was.
    Float4 origin[3], inverse[3];
    int near[3];
    for (int axis = 0; axis < 3; ++axis) {
        const float reciprocal = 1.0f / ray.direction[axis];
        origin[axis] = Float4{} + ray.origin[axis];
        inverse[axis] = Float4{} + reciprocal;
        near[axis] = 2 * axis + (reciprocal < 0.0f);
    }
    // The lane walked now: the nearest one met, the others left on the stack.
    Pending current{0, 0, ray.tMin};
    for (;;) {
        if (current.entry <= ray.tMax && current.count > 0) {
            for (uint32_t i = current.first; i < current.first + current.count; ++i)
                if (visit(bvh.items[i])) return;
        } else if (current.entry <= ray.tMax) {
            const WideBvhNode& node = bvh.nodes[current.first];
            Float4 enter = Float4{} + ray.tMin, leave = Float4{} + ray.tMax;
            for (int axis = 0; axis < 3; ++axis) {
                const Float4 nearT = (node.planes[near[axis]] - origin[axis]) * inverse[axis];
                const Float4 farT = (node.planes[near[axis] ^ 1] - origin[axis]) * inverse[axis];
                enter = nearT > enter ? nearT : enter;
                leave = farT < leave ? farT : leave;
            }
            // The lanes met, farthest first; the nearest is walked next (of
            // two at the same distance, the first lane, as traverseBvh's).
            uint32_t met[kWideBvhLanes], metCount = 0;
            for (uint32_t lane = 0; lane < kWideBvhLanes; ++lane) {
                if (!(enter[lane] <= leave[lane]) || node.count[lane] == kEmptyLane) continue;
                uint32_t at = metCount++;
                for (; at > 0 && enter[met[at - 1]] <= enter[lane]; --at) met[at] = met[at - 1];
                met[at] = lane;
            }
            if (metCount > 0) {
                for (uint32_t i = 0; i + 1 < metCount; ++i)
                    stack[size++] = {node.first[met[i]], node.count[met[i]], enter[met[i]]};
                const uint32_t nearest = met[metCount - 1];
                current = {node.first[nearest], node.count[nearest], enter[nearest]};
                continue;
            }
        }
        if (size == 0) return;
        current = stack[--size]; // skipped above if a nearer hit was found since it was pushed
    }
}

} // namespace lsys
