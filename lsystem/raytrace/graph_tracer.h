#pragma once
// Tracing an InstanceGraph without flattening it (docs/RAYTRACING.md): each
// object has a BVH over its items (its own primitives by their boxes, its
// child instances by their objects' boxes placed by the instance frames); a
// ray entering an instance is carried into the child's local frame, so every
// object is stored once however many times it is placed (the Calgary
// b-grammar thesis, ch. 7, ray-traces its instancing hierarchies so; Robbins
// 1998 traces an L-system's branches near to far, ending shadow rays at their
// first hit). The walk recurses once per level of instances, as flatten does.

#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "lsystem/instance_graph.h"
#include "lsystem/raytrace/bvh.h"
#include "lsystem/raytrace/ray.h"
#include "lsystem/raytrace/traced_primitive.h"
#include "lsystem/surfaces.h"

namespace lsys {

struct GraphTracer {
    const InstanceGraph* graph = nullptr;   // must outlive the tracer
    std::vector<Primitive> primitives;      // InstanceGraph::primitives as flat records
    std::vector<glm::quat> instanceToLocal; // the inverse of each InstanceGraph::instances rotation
    TracedShapes shapes;
    std::vector<Bounds> objectBounds; // of what each object's subtree draws, in its local space
    std::vector<Bvh> objectBvhs;      // over each object's items, in itemsOf order
};

// An object's BVH (in either graph tracer) has one item a leaf: an instance is a whole subtree, worth
// its own box test before the ray is carried into it, and its own place in
// the near-to-far order, so a closest-hit query finds the nearer subtree's
// hit before it walks a farther one.
inline constexpr uint32_t kGraphObjectLeafSize = 1;

// Traces an instance (`toLocal`: the inverse of its rotation): the ray carried into the child's frame, traced there
// by `traceChild(object, localRay, localHit)` (true on a hit nearer than
// localRay.tMax), and a hit brought back, lowering ray.tMax. Shared by the
// graph tracers, whichever way they hold an object's items.
template <typename TraceChild>
bool traceInstance(const GraphInstance& instance, const glm::quat& toLocal, Ray& ray, Hit& hit,
                   TraceChild&& traceChild) {
    Ray local = rayInFrame(ray, instance.frame.position, toLocal);
    Hit inner;
    if (!traceChild(instance.object, local, inner)) return false;
    inner.normal = glm::normalize(instance.frame.rotation * inner.normal);
    hit = inner;
    ray.tMax = inner.t;
    return true;
}

// Built once: objects children first, so each object's instances are boxed
// by boxes already known. Throws SurfaceError for a surface the graph's look
// and `surfaces` lack.
GraphTracer buildGraphTracer(const InstanceGraph& graph, const SurfaceLibrary& surfaces = SurfaceLibrary{});

// As trace(FlatTracer): the hit's primitive indexes InstanceGraph::primitives
// (which object path reached it is not kept), its normal is in plant space.
std::optional<Hit> trace(const GraphTracer& tracer, Ray ray, HitQuery query);

} // namespace lsys
