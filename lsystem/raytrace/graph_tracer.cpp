#include "lsystem/raytrace/graph_tracer.h"

#include <algorithm>
#include <array>

#include "lsystem/turtle/turtle.h"

namespace lsys {
namespace {

// An instance's box in its parent is the box of its object's box placed by
// its frame, which is larger than what the object draws unless the frame
// only translates; boxes of boxes placed level upon level (a fractal bush's
// twelve) grow with every level. So an object's items are boxed from their
// descendants instead, down to kMaxLookahead levels or kLookaheadBudget boxes
// placed per object (and kTotalLookaheadBudget for all objects, so a graph
// of a million objects is built in about a second): primitives boxed in their
// composed frames, deeper instances by their objects' boxes. The boxes still
// hold everything drawn, so the hits are the same; fewer rays enter instances
// they miss.
constexpr int kMaxLookahead = 4;
constexpr uint64_t kLookaheadBudget = 4096;
constexpr uint64_t kTotalLookaheadBudget = uint64_t(1) << 24;

// Per object, the boxes placed to box it looking 0 to kMaxLookahead levels down.
using BoxCosts = std::vector<std::array<uint64_t, kMaxLookahead + 1>>;

BoxCosts boxCostsOf(const InstanceGraph& graph) {
    BoxCosts costs(graph.objects.size());
    for (uint32_t object = 0; object < graph.objects.size(); ++object) { // children first
        costs[object][0] = 1;
        for (int depth = 1; depth <= kMaxLookahead; ++depth)
            for (const GraphItem& item : graph.itemsOf(object))
                costs[object][depth] =
                    std::min(kLookaheadBudget + 1,
                             costs[object][depth] + (item.kind == GraphItem::Kind::Primitive
                                                         ? 1
                                                         : costs[graph.instances[item.index].object][depth - 1]));
    }
    return costs;
}

// How many levels down an object is boxed from, placing at most `budget`
// boxes beyond its own items (which it always boxes); `budget` is lowered by them.
int lookahead(const BoxCosts& costs, uint32_t object, uint64_t& budget) {
    int depth = 1;
    while (depth < kMaxLookahead && costs[object][depth + 1] <= std::min(kLookaheadBudget, budget)) ++depth;
    budget -= std::min(budget, costs[object][depth]);
    return depth;
}

Bounds placedPrimitiveBounds(const GraphTracer& tracer, const Primitive& primitive, const Frame& frame) {
    // A polygon's outline is in its object's space already; its frame is not applied.
    if (primitive.kind == PrimitiveKind::Polygon)
        return transformed(tracedBounds(primitive, tracer.shapes.surfaces, tracer.shapes.polygons), frame);
    Primitive placed = primitive;
    placed.frame = compose(frame, primitive.frame);
    return tracedBounds(placed, tracer.shapes.surfaces, tracer.shapes.polygons);
}

// The box of what `object` draws placed by `frame`, its items boxed
// `depth` levels down (its own box placed at 0).
Bounds placedBounds(const GraphTracer& tracer, uint32_t object, const Frame& frame, int depth) {
    if (depth == 0) return transformed(tracer.objectBounds[object], frame);
    const InstanceGraph& graph = *tracer.graph;
    Bounds bounds;
    for (const GraphItem& item : graph.itemsOf(object)) {
        if (item.kind == GraphItem::Kind::Primitive) {
            bounds.extend(placedPrimitiveBounds(tracer, tracer.primitives[item.index], frame));
        } else {
            const GraphInstance& instance = graph.instances[item.index];
            bounds.extend(placedBounds(tracer, instance.object, compose(frame, instance.frame), depth - 1));
        }
    }
    return bounds;
}

// At most this many primitives over all flattened objects.
constexpr uint64_t kFlattenedTotal = uint64_t(1) << 19;

// Appends what `object` draws, placed by `frame` (none: the flattened object
// itself, whose own primitives keep their records), to `flat`.
void flattenSubtree(const GraphTracer& tracer, uint32_t object, const Frame* frame, FlattenedObject& flat,
                    std::vector<Bounds>& boxes) {
    const InstanceGraph& graph = *tracer.graph;
    for (const GraphItem& item : graph.itemsOf(object)) {
        if (item.kind == GraphItem::Kind::Instance) {
            const GraphInstance& instance = graph.instances[item.index];
            const Frame placed = frame ? compose(*frame, instance.frame) : instance.frame;
            flattenSubtree(tracer, instance.object, &placed, flat, boxes);
            continue;
        }
        const Primitive& primitive = tracer.primitives[item.index];
        const Bounds box = frame ? placedPrimitiveBounds(tracer, primitive, *frame)
                                 : tracedBounds(primitive, tracer.shapes.surfaces, tracer.shapes.polygons);
        if (box.empty()) continue;
        FlattenedObject::Leaf leaf{primitive.frame, tracer.primitiveToLocal[item.index], item.index};
        if (primitive.kind == PrimitiveKind::Polygon) {
            leaf.frame = frame ? *frame : Frame{};
            leaf.toLocal = glm::inverse(leaf.frame.rotation);
        } else if (frame) {
            leaf.frame = compose(*frame, primitive.frame);
            leaf.toLocal = glm::inverse(leaf.frame.rotation);
        }
        flat.leaves.push_back(leaf);
        boxes.push_back(box);
    }
}

FlattenedObject flattenedObject(const GraphTracer& tracer, uint32_t object) {
    FlattenedObject flat;
    std::vector<Bounds> boxes;
    flattenSubtree(tracer, object, nullptr, flat, boxes);
    flat.bvh = widen(buildBvh(boxes, kGraphObjectLeafSize));
    // The leaves in the order the BVH's leaves hold them, so a walk reads
    // them from nearby memory rather than across the flattening order.
    std::vector<FlattenedObject::Leaf> leaves;
    leaves.reserve(flat.bvh.items.size());
    for (uint32_t& item : flat.bvh.items) {
        leaves.push_back(flat.leaves[item]);
        item = uint32_t(leaves.size() - 1);
    }
    flat.leaves = std::move(leaves);
    return flat;
}

// Tests a flattened object's leaf against the ray in the object's space, as
// tracePrimitive does with the primitive placed there: a polygon after
// carrying the ray into the frame of the object that drew it, its normal
// turned back.
bool traceLeaf(const GraphTracer& tracer, const FlattenedObject::Leaf& leaf, Ray& ray, Hit& hit) {
    Primitive placed = tracer.primitives[leaf.primitive];
    if (placed.kind != PrimitiveKind::Polygon) {
        placed.frame = leaf.frame;
        return tracePrimitive(placed, leaf.toLocal, leaf.primitive, tracer.shapes.surfaces, tracer.shapes.polygons, ray,
                              hit);
    }
    Ray local = rayInFrame(ray, leaf.frame.position, leaf.toLocal);
    if (!tracePrimitive(placed, leaf.toLocal, leaf.primitive, tracer.shapes.surfaces, tracer.shapes.polygons, local,
                        hit))
        return false;
    hit.normal = glm::normalize(leaf.frame.rotation * hit.normal);
    ray.tMax = hit.t;
    return true;
}

bool traceFlattened(const GraphTracer& tracer, const FlattenedObject& flat, Ray& ray, HitQuery query, Hit& hit) {
    bool found = false;
    traverseWideBvh(flat.bvh, ray, [&](uint32_t i) {
        found |= traceLeaf(tracer, flat.leaves[i], ray, hit);
        return found && query == HitQuery::Any;
    });
    return found;
}

// Traces one object with the ray in its local space: true when it found a hit
// nearer than ray.tMax, which is then lowered to it; `hit` in local space.
bool traceObject(const GraphTracer& tracer, uint32_t object, Ray& ray, HitQuery query, Hit& hit) {
    if (tracer.flattenedIndex[object] != kNotFlattened)
        return traceFlattened(tracer, tracer.flattened[tracer.flattenedIndex[object]], ray, query, hit);
    const InstanceGraph& graph = *tracer.graph;
    const std::span<const GraphItem> items = graph.itemsOf(object);
    bool found = false;
    traverseWideBvh(tracer.objectWideBvhs[object], ray, [&](uint32_t i) {
        const GraphItem& item = items[i];
        if (item.kind == GraphItem::Kind::Primitive) {
            found |= tracePrimitive(tracer.primitives[item.index], tracer.primitiveToLocal[item.index], item.index,
                                    tracer.shapes.surfaces, tracer.shapes.polygons, ray, hit);
        } else {
            found |= traceInstance(graph.instances[item.index], tracer.instanceToLocal[item.index], ray, hit,
                                   [&](uint32_t child, Ray& local, Hit& inner) {
                                       return traceObject(tracer, child, local, query, inner);
                                   });
        }
        return found && query == HitQuery::Any;
    });
    return found;
}

// What the CPU walk enters, parents first (the reverse of the graph's
// order): the root, and the children of every object entered but not
// flattened.
void prepareWalk(GraphTracer& tracer, uint64_t flattenedPrimitives) {
    const InstanceGraph& graph = *tracer.graph;
    tracer.flattenedIndex.assign(graph.objects.size(), kNotFlattened);
    tracer.objectWideBvhs.resize(graph.objects.size());
    if (graph.objects.empty()) return;
    std::vector<bool> entered(graph.objects.size(), false);
    entered[graph.root] = true;
    uint64_t flattenedTotal = 0;
    for (uint32_t object = uint32_t(graph.objects.size()); object-- > 0;) {
        if (!entered[object]) continue;
        const uint64_t primitives = graph.objects[object].primitives;
        if (flattenedPrimitives > 0 && primitives <= flattenedPrimitives &&
            flattenedTotal + primitives <= kFlattenedTotal) {
            flattenedTotal += primitives;
            tracer.flattenedIndex[object] = uint32_t(tracer.flattened.size());
            tracer.flattened.push_back(flattenedObject(tracer, object));
            continue;
        }
        tracer.objectWideBvhs[object] = widen(tracer.objectBvhs[object]);
        for (const GraphItem& item : graph.itemsOf(object))
            if (item.kind == GraphItem::Kind::Instance) entered[graph.instances[item.index].object] = true;
    }
}

} // namespace

GraphTracer buildGraphTracer(const InstanceGraph& graph, const SurfaceLibrary& surfaces, uint64_t flattenedPrimitives) {
    GraphTracer tracer{&graph, {}, {}, {}, tracedShapesOf(graph, surfaces), {}, {}, {}, {}, {}};
    // Pixel-wide lines get the world width graph export gives them (the
    // root's box over kPixelsAcrossPlant), which flattening matches when
    // the root's box is the plant's.
    const float lineScale =
        graph.pixelLines && !graph.objects.empty() ? worldPerPixel(graph.objects[graph.root].bounds) : 1.0f;
    tracer.primitives.reserve(graph.primitives.size());
    tracer.primitiveToLocal.reserve(graph.primitives.size());
    for (const GraphPrimitive& primitive : graph.primitives) {
        tracer.primitives.push_back(tracedPrimitive(primitive, lineScale));
        tracer.primitiveToLocal.push_back(glm::inverse(primitive.frame.rotation));
    }
    tracer.instanceToLocal.reserve(graph.instances.size());
    for (const GraphInstance& instance : graph.instances)
        tracer.instanceToLocal.push_back(glm::inverse(instance.frame.rotation));
    tracer.objectBounds.resize(graph.objects.size());
    tracer.objectBvhs.resize(graph.objects.size());
    const BoxCosts costs = boxCostsOf(graph);
    uint64_t lookaheadBudget = kTotalLookaheadBudget;
    std::vector<Bounds> itemBounds;
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        const int depth = lookahead(costs, object, lookaheadBudget);
        itemBounds.clear();
        for (const GraphItem& item : graph.itemsOf(object)) {
            if (item.kind == GraphItem::Kind::Primitive) {
                itemBounds.push_back(
                    tracedBounds(tracer.primitives[item.index], tracer.shapes.surfaces, tracer.shapes.polygons));
            } else {
                const GraphInstance& instance = graph.instances[item.index];
                itemBounds.push_back(placedBounds(tracer, instance.object, instance.frame, depth - 1));
            }
            tracer.objectBounds[object].extend(itemBounds.back());
        }
        tracer.objectBvhs[object] = buildBvh(itemBounds, kGraphObjectLeafSize);
    }
    prepareWalk(tracer, flattenedPrimitives);
    return tracer;
}

std::optional<Hit> trace(const GraphTracer& tracer, Ray ray, HitQuery query) {
    if (tracer.graph->objects.empty()) return std::nullopt;
    Hit hit;
    if (!traceObject(tracer, tracer.graph->root, ray, query, hit)) return std::nullopt;
    return hit;
}

} // namespace lsys
