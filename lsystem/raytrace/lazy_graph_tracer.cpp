#include "lsystem/raytrace/lazy_graph_tracer.h"

#include <array>
#include <utility>

#include "lsystem/raytrace/graph_tracer.h"
#include "lsystem/turtle/turtle.h"

namespace lsys {
namespace {

template <typename T>
uint64_t capacityBytes(const std::vector<T>& values) {
    return values.capacity() * sizeof(T);
}

// The object's items interpreted again, with GraphTracer's records, boxes
// and BVH; `bounds` set to the union of the item boxes.
ExpandedObject expandForTracing(const LazyGraphTracer& tracer, uint32_t object, Bounds& bounds) {
    ObjectExpansion expansion = expandObject(*tracer.graph, object);
    ExpandedObject expanded{std::move(expansion.items),         {},
                            std::move(expansion.primitiveIds),  std::move(expansion.instances),
                            tracedPolygons(expansion.polygons), {}};
    expanded.primitives.reserve(expansion.primitives.size());
    for (const GraphPrimitive& primitive : expansion.primitives)
        expanded.primitives.push_back(tracedPrimitive(primitive, tracer.lineScale));
    std::vector<Bounds> itemBounds;
    itemBounds.reserve(expanded.items.size());
    bounds = {};
    for (const GraphItem& item : expanded.items) {
        if (item.kind == GraphItem::Kind::Primitive) {
            itemBounds.push_back(tracedBounds(expanded.primitives[item.index], tracer.surfaces, expanded.polygons));
        } else {
            const GraphInstance& instance = expanded.instances[item.index];
            itemBounds.push_back(transformed(tracer.objectBounds[instance.object], instance.frame));
        }
        bounds.extend(itemBounds.back());
    }
    expanded.bvh = buildBvh(itemBounds, kGraphObjectLeafSize);
    return expanded;
}

// The object's expansion: the cache's, or made now and offered to it.
std::shared_ptr<const ExpandedObject> expansionOf(const LazyGraphTracer& tracer, uint32_t object) {
    if (std::shared_ptr<const ExpandedObject> held = findExpansion(*tracer.cache, object)) return held;
    Bounds bounds;
    auto made = std::make_shared<const ExpandedObject>(expandForTracing(tracer, object, bounds));
    const uint64_t bytes = byteSize(*made);
    return holdExpansion(*tracer.cache, object, std::move(made), bytes);
}

// The expansions one trace() has fetched. A ray meets an instanced object
// many times (a deep bush's twig thousands of times); found here, it costs
// no lock and no shared reference count, so threads tracing at once meet
// the cache once per object and ray. Each stays alive until the trace
// returns, whether the cache evicts it meanwhile or never held it.
struct TracePins {
    static constexpr uint32_t kSlots = 64;
    std::array<std::pair<uint32_t, const ExpandedObject*>, kSlots> slots; // by object modulo kSlots
    std::vector<std::shared_ptr<const ExpandedObject>> held;
    TracePins() { slots.fill({UINT32_MAX, nullptr}); }
};

const ExpandedObject& pinned(const LazyGraphTracer& tracer, uint32_t object, TracePins& pins) {
    std::pair<uint32_t, const ExpandedObject*>& slot = pins.slots[object % TracePins::kSlots];
    if (slot.first != object) {
        pins.held.push_back(expansionOf(tracer, object));
        slot = {object, pins.held.back().get()};
    }
    return *slot.second;
}

// As GraphTracer's traceObject; the object is expanded only once the ray
// met its box (its parent's BVH tested it).
bool traceObject(const LazyGraphTracer& tracer, uint32_t object, TracePins& pins, Ray& ray, HitQuery query, Hit& hit) {
    const ExpandedObject& expansion = pinned(tracer, object, pins);
    bool found = false;
    traverseBvh(expansion.bvh, ray, [&](uint32_t i) {
        const GraphItem& item = expansion.items[i];
        if (item.kind == GraphItem::Kind::Primitive) {
            found |= tracePrimitive(expansion.primitives[item.index], expansion.primitiveIds[item.index],
                                    tracer.surfaces, expansion.polygons, ray, hit);
        } else {
            found |= traceInstance(expansion.instances[item.index],
                                   glm::inverse(expansion.instances[item.index].frame.rotation), ray, hit,
                                   [&](uint32_t child, Ray& local, Hit& inner) {
                                       return traceObject(tracer, child, pins, local, query, inner);
                                   });
        }
        return found && query == HitQuery::Any;
    });
    return found;
}

} // namespace

uint64_t byteSize(const ExpandedObject& object) {
    uint64_t bytes = sizeof(ExpandedObject) + capacityBytes(object.items) + capacityBytes(object.primitives) +
                     capacityBytes(object.primitiveIds) + capacityBytes(object.instances) +
                     capacityBytes(object.polygons.meshes) + capacityBytes(object.polygons.bounds) +
                     capacityBytes(object.bvh.nodes) + capacityBytes(object.bvh.items);
    for (const TriangleMesh& mesh : object.polygons.meshes)
        bytes += capacityBytes(mesh.positions) + capacityBytes(mesh.normals) + capacityBytes(mesh.uvs) +
                 capacityBytes(mesh.indices);
    return bytes;
}

LazyGraphTracer buildLazyGraphTracer(const LazyInstanceGraph& graph, uint64_t budgetBytes,
                                     const SurfaceLibrary& surfaces) {
    const InstanceGraph& objects = graph.graph;
    LazyGraphTracer tracer{
        &graph, tracedShapesOf(objects, surfaces).surfaces, 1.0f, {}, std::make_unique<ExpansionCache>()};
    // Pixel-wide lines: as buildGraphTracer.
    if (objects.pixelLines && !objects.objects.empty())
        tracer.lineScale = worldPerPixel(objects.objects[objects.root].bounds);
    tracer.objectBounds.resize(objects.objects.size());
    for (uint32_t object = 0; object < objects.objects.size(); ++object)
        expandForTracing(tracer, object, tracer.objectBounds[object]);
    tracer.cache->budgetBytes = budgetBytes;
    tracer.cache->objects.resize(objects.objects.size());
    return tracer;
}

std::optional<Hit> trace(const LazyGraphTracer& tracer, Ray ray, HitQuery query) {
    const InstanceGraph& graph = tracer.graph->graph;
    // A ray missing the root's box misses its BVH's root: nothing to expand.
    if (graph.objects.empty() || !boxEntry(ray, tracer.objectBounds[graph.root])) return std::nullopt;
    Hit hit;
    TracePins pins;
    if (!traceObject(tracer, graph.root, pins, ray, query, hit)) return std::nullopt;
    return hit;
}

ExpansionStats expansionStats(const LazyGraphTracer& tracer) { return expansionStats(*tracer.cache); }

} // namespace lsys
