#include "lsystem/raytrace/graph_tracer.h"

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
            found |= traceInstance(graph.instances[item.index], ray, hit, [&](uint32_t child, Ray& local, Hit& inner) {
                return traceObject(tracer, child, local, query, inner);
            });
        }
        return found && query == HitQuery::Any;
    });
    return found;
}

} // namespace

GraphTracer buildGraphTracer(const InstanceGraph& graph, const SurfaceLibrary& surfaces) {
    GraphTracer tracer{&graph, {}, tracedShapesOf(graph, surfaces), {}, {}};
    // Pixel-wide lines get the world width graph export gives them (the
    // root's box over kPixelsAcrossPlant), which flattening matches when
    // the root's box is the plant's.
    const float lineScale =
        graph.pixelLines && !graph.objects.empty() ? worldPerPixel(graph.objects[graph.root].bounds) : 1.0f;
    tracer.primitives.reserve(graph.primitives.size());
    for (const GraphPrimitive& primitive : graph.primitives)
        tracer.primitives.push_back(tracedPrimitive(primitive, lineScale));
    tracer.objectBounds.resize(graph.objects.size());
    tracer.objectBvhs.resize(graph.objects.size());
    std::vector<Bounds> itemBounds;
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        itemBounds.clear();
        for (const GraphItem& item : graph.itemsOf(object)) {
            if (item.kind == GraphItem::Kind::Primitive) {
                itemBounds.push_back(
                    tracedBounds(tracer.primitives[item.index], tracer.shapes.surfaces, tracer.shapes.polygons));
            } else {
                const GraphInstance& instance = graph.instances[item.index];
                itemBounds.push_back(transformed(tracer.objectBounds[instance.object], instance.frame));
            }
            tracer.objectBounds[object].extend(itemBounds.back());
        }
        tracer.objectBvhs[object] = buildBvh(itemBounds);
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
