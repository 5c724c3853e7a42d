#pragma once
// An InstanceGraph whose objects are expanded on demand (docs/RAYTRACING.md,
// "Lazy expansion"), as Robbins 1998 (§3) expands an L-system's branches
// inside the ray tracer: a b-grammar node with its remaining derivation steps
// is his [branch, iterations] pair, and an object (node + the entry values
// it read) can be interpreted again from its entry alone.
//
// deriveLazyInstanceGraph interprets every object once, as
// buildInstanceGraph does, but keeps only the objects (node, bounds, counts)
// and what replaying one needs: its entry turtle state and status function,
// and where the build's numbering of objects and primitives stood. Its items,
// primitives, instance frames and polygons are dropped; expandObject
// interprets the object's body again and gives them back, bit for bit what
// buildInstanceGraph stores, numbered as it numbers them.

#include <cstdint>
#include <memory>
#include <vector>

#include "lsystem/instancing/instance_graph.h"

namespace lsys {

// One object's share of an InstanceGraph, in itemsOf order.
struct ObjectExpansion {
    std::vector<GraphItem> items;           // indices into primitives or instances below
    std::vector<GraphPrimitive> primitives; // a polygon's shape indexes polygons below
    std::vector<uint32_t> primitiveIds;     // each primitive's index in buildInstanceGraph's primitives
    std::vector<GraphInstance> instances;
    std::vector<PolygonShape> polygons;
};

// The builder kept to replay objects (the b-grammar, options and surface folders copied in).
struct GraphDerivation;

struct LazyInstanceGraph {
    // As buildInstanceGraph's, without items, primitives, instances and
    // polygons: every GraphObject's itemCount is 0.
    InstanceGraph graph;
    std::shared_ptr<const GraphDerivation> derivation;
};

// As buildInstanceGraph, with the same errors.
LazyInstanceGraph deriveLazyInstanceGraph(const BGrammar& bgrammar, const Grammar& grammar,
                                          const InstanceGraphOptions& options = {},
                                          const SurfaceLibrary& surfaces = SurfaceLibrary{});

// materialsOf(buildInstanceGraph(…)) without the whole graph: every object
// expanded once, one at a time.
std::vector<Material> materialsOf(const LazyInstanceGraph& graph);

// The items of one object, interpreted again. Changes nothing: threads may
// expand objects of one graph at once.
ObjectExpansion expandObject(const LazyInstanceGraph& graph, uint32_t object);

} // namespace lsys
