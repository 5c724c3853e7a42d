#include "lsystem/raytrace/graph_tracer.h"

#include <algorithm>
#include <array>

#include "lsystem/turtle.h"

namespace lsys {
namespace {

// Traces one object with the ray in its local space: true when it found a hit
// nearer than ray.tMax, which is then lowered to it; `hit` in local space.
bool traceObject(const GraphTracer& tracer, uint32_t object, Ray& ray, HitQuery query, Hit& hit) {
    const InstanceGraph& graph = *tracer.graph;
    const std::span<const GraphItem> items = graph.itemsOf(object);
    bool found = false;
    traverseBvh(tracer.objectBvhs[object], ray, [&](uint32_t i) {
        const GraphItem& item = items[i];
        if (item.kind == GraphItem::Kind::Primitive) {
            found |= tracePrimitive(tracer.primitives[item.index], item.index, tracer.shapes.surfaces,
                                    tracer.shapes.polygons, ray, hit);
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

} // namespace

GraphTracer buildGraphTracer(const InstanceGraph& graph, const SurfaceLibrary& surfaces) {
    GraphTracer tracer{&graph, {}, {}, tracedShapesOf(graph, surfaces), {}, {}};
    // Pixel-wide lines get the world width graph export gives them (the
    // root's box over kPixelsAcrossPlant), which flattening matches when
    // the root's box is the plant's.
    const float lineScale =
        graph.pixelLines && !graph.objects.empty() ? worldPerPixel(graph.objects[graph.root].bounds) : 1.0f;
    tracer.primitives.reserve(graph.primitives.size());
    for (const GraphPrimitive& primitive : graph.primitives)
        tracer.primitives.push_back(tracedPrimitive(primitive, lineScale));
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
    return tracer;
}

std::optional<Hit> trace(const GraphTracer& tracer, Ray ray, HitQuery query) {
    if (tracer.graph->objects.empty()) return std::nullopt;
    Hit hit;
    if (!traceObject(tracer, tracer.graph->root, ray, query, hit)) return std::nullopt;
    return hit;
}

} // namespace lsys
