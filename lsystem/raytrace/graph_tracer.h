#pragma once
// Tracing an InstanceGraph without flattening it (docs/RAYTRACING.md): each
// object has a BVH over its items (its own primitives by their boxes, its
// child instances by their objects' boxes placed by the instance frames); a
// ray entering an instance is carried into the child's local frame, so every
// object is stored once however many times it is placed (the Calgary
// b-grammar thesis, ch. 7, ray-traces its instancing hierarchies so; Robbins
// 1998 traces an L-system's branches near to far, ending shadow rays at their
// first hit). The walk recurses once per level of instances, as flatten does,
// down to objects small enough to be walked through one BVH over all that
// their subtree draws (FlattenedObject). The GPU traversal
// (engine/raytrace) packs objectBvhs and walks every instance.

#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "lsystem/instancing/instance_graph.h"
#include "lsystem/raytrace/bvh.h"
#include "lsystem/raytrace/ray.h"
#include "lsystem/raytrace/traced_primitive.h"
#include "lsystem/raytrace/wide_bvh.h"
#include "lsystem/turtle/surfaces.h"

namespace lsys {

// An object whose subtree draws few primitives, walked through one BVH over
// all of them, each placed in the object's space by the frames of its path
// of instances composed: overlapping instances (a bush's sub-bushes) no
// longer make a ray enter every one whose box it meets, only the
// primitives' own boxes count, and a primitive costs one change of frame
// instead of one per level. The hits are those of the walk through the
// instances up to rounding (the composed frames round differently).
struct FlattenedObject {
    struct Leaf {
        // Where the primitive is placed in the object's space (for a
        // polygon, the object that drew it: its outline is in that space).
        Frame frame;
        glm::quat toLocal;  // the inverse of frame's rotation
        uint32_t primitive; // into InstanceGraph::primitives: the hit's index
    };
    std::vector<Leaf> leaves; // in the order of the BVH's items
    WideBvh bvh;              // over leaves, by their boxes in the object's space
};

struct GraphTracer {
    const InstanceGraph* graph = nullptr;    // must outlive the tracer
    std::vector<Primitive> primitives;       // InstanceGraph::primitives as flat records
    std::vector<glm::quat> primitiveToLocal; // the inverse of each one's rotation
    std::vector<glm::quat> instanceToLocal;  // the inverse of each InstanceGraph::instances rotation
    TracedShapes shapes;
    std::vector<Bounds> objectBounds; // of what each object's subtree draws, in its local space
    std::vector<Bvh> objectBvhs;      // over each object's items, in itemsOf order (what the GPU walks)
    // What the CPU walk enters, per object: its whole subtree flattened, or
    // else objectBvhs widened (empty for objects the walk never enters: those
    // only inside flattened ones).
    std::vector<uint32_t> flattenedIndex; // into `flattened`, or kNotFlattened
    std::vector<FlattenedObject> flattened;
    std::vector<WideBvh> objectWideBvhs;
};

inline constexpr uint32_t kNotFlattened = UINT32_MAX;

// Objects entered by the walk whose subtree draws at most this many
// primitives are flattened (up to 2^19 primitives over all of them, some
// 60 MB: 48 bytes a placed primitive, 58 of wide BVH). A fractal bush's
// 5-step sub-bush is 32 768; flattening its 4- or 6-step one (4 096 or
// 262 144) traced its 12-step image more slowly.
inline constexpr uint64_t kFlattenedPrimitives = 32768;
// Nothing flattened: every instance walked, as the lazy tracer and the GPU
// traversal walk them.
inline constexpr uint64_t kNoFlattening = 0;

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
GraphTracer buildGraphTracer(const InstanceGraph& graph, const SurfaceLibrary& surfaces = SurfaceLibrary{},
                             uint64_t flattenedPrimitives = kFlattenedPrimitives);

// As trace(FlatTracer): the hit's primitive indexes InstanceGraph::primitives
// (which object path reached it is not kept), its normal is in plant space.
std::optional<Hit> trace(const GraphTracer& tracer, Ray ray, HitQuery query);

} // namespace lsys
