#pragma once
// Tracing a LazyInstanceGraph (docs/RAYTRACING.md, "Lazy expansion"), after
// Robbins 1998, §3: an object's items are interpreted from the b-grammar
// only when a ray enters the object's box, kept in an LRU cache under a byte
// budget, and interpreted again when needed after eviction. Its closest hits
// are GraphTracer's on buildInstanceGraph's graph whatever the budget (where
// copies of a shape overlap exactly, possibly the other copy): instances are
// boxed by their objects' boxes only, since descendants are not at hand.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "lsystem/instancing/instance_graph_lazy.h"
#include "lsystem/raytrace/bvh.h"
#include "lsystem/raytrace/expansion_cache.h"
#include "lsystem/raytrace/ray.h"
#include "lsystem/raytrace/traced_primitive.h"
#include "lsystem/turtle/surfaces.h"

namespace lsys {

// One object made ready to trace: GraphTracer's share of it.
struct ExpandedObject {
    std::vector<GraphItem> items;
    std::vector<Primitive> primitives;  // the expansion's, as flat records
    std::vector<uint32_t> primitiveIds; // their indices in buildInstanceGraph's graph
    std::vector<GraphInstance> instances;
    TracedMeshes polygons;
    Bvh bvh; // over the items
};

// The memory an expansion holds (its arrays' capacities).
uint64_t byteSize(const ExpandedObject& object);

struct LazyGraphTracer {
    const LazyInstanceGraph* graph = nullptr; // must outlive the tracer
    TracedMeshes surfaces;
    float lineScale = 1.0f;           // as GraphTracer's
    std::vector<Bounds> objectBounds; // as GraphTracer's
    // Changed by tracing, whence behind a pointer: trace() takes the tracer const.
    std::unique_ptr<ExpansionCache> cache;
};

// Expands every object once, children first, for its box (GraphTracer's,
// from its items' traced boxes), and holds none of them: the cache starts
// empty. Throws SurfaceError for a surface the graph's look and `surfaces` lack.
LazyGraphTracer buildLazyGraphTracer(const LazyInstanceGraph& graph, uint64_t budgetBytes,
                                     const SurfaceLibrary& surfaces = SurfaceLibrary{});

// As trace(GraphTracer); threads may trace one tracer at once.
std::optional<Hit> trace(const LazyGraphTracer& tracer, Ray ray, HitQuery query);

ExpansionStats expansionStats(const LazyGraphTracer& tracer);

} // namespace lsys
