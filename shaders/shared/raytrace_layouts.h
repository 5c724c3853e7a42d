// GPU layout of a plant's InstanceGraph packed for ray tracing
// (engine/raytrace/gpu_graph.h, docs/RAYTRACING.md "The GPU traversal"),
// shared by GLSL (shaders/raytrace_traverse.glsl) and C++. Every object's
// BVH (lsystem/raytrace/bvh.h) is stored in one node array; node and item
// indices are global, so the traversal needs no per-object offsets.
#ifndef PLANTFIELD_SHADERS_RAYTRACE_LAYOUTS_H
#define PLANTFIELD_SHADERS_RAYTRACE_LAYOUTS_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace gpu {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uint = uint32_t;
#endif

#define RAYTRACE_GROUP_SIZE 64 // invocations of raytrace_rays.comp, one a ray

// The graph's uniform texel buffers (RAYTRACE_GRAPH_SET, chosen by the
// shader that includes raytrace_traverse.glsl; uint views of 16-byte texels,
// a record RAYTRACE_*_TEXELS of them, or of 4-byte texels) and
// raytrace_rays.comp's storage buffers of rays and hits.
#define RAYTRACE_BINDING_NODES 0        // RtNode[]
#define RAYTRACE_BINDING_ITEMS 1        // uint[] (4-byte texels): RAYTRACE_ITEM_INSTANCE | an instance, or a primitive
#define RAYTRACE_BINDING_OBJECT_ROOTS 2 // uint[] (4-byte texels) per object: its BVH's root node, or RAYTRACE_NO_NODE
#define RAYTRACE_BINDING_INSTANCES 3    // RtInstance[]
#define RAYTRACE_BINDING_PRIMITIVES 4   // RtPrimitive[], by InstanceGraph::primitives index
#define RAYTRACE_BINDING_TRIANGLES 5    // RtTriangle[] of surfaces and polygons
#define RAYTRACE_BINDING_RAYS 6         // RtRay[]
#define RAYTRACE_BINDING_HITS 7         // RtHit[], one per ray

#define RAYTRACE_NODE_TEXELS 2
#define RAYTRACE_INSTANCE_TEXELS 3
#define RAYTRACE_PRIMITIVE_TEXELS 4
#define RAYTRACE_TRIANGLE_TEXELS 3

// The traversal's fixed arrays: the instance levels a ray is carried through
// (the root object is level 0) and the stack of nodes still to visit. A graph
// that could need more is refused when it is packed (packGraph), never cut
// short on the GPU.
#define RAYTRACE_MAX_LEVELS 16
#define RAYTRACE_STACK_SIZE 96

#define RAYTRACE_NO_NODE 0xffffffffu
#define RAYTRACE_NO_HIT 0xffffffffu        // RtHit::primitive of a ray that hit nothing
#define RAYTRACE_ITEM_INSTANCE 0x80000000u // set on an item that is an instance; the rest is its index

// lsys::PrimitiveKind's values.
#define RAYTRACE_KIND_SEGMENT 0u
#define RAYTRACE_KIND_SPHERE 1u
#define RAYTRACE_KIND_SURFACE 2u
#define RAYTRACE_KIND_POLYGON 3u

// lsys::HitQuery's values.
#define RAYTRACE_QUERY_CLOSEST 0u
#define RAYTRACE_QUERY_ANY 1u

// lsys::BvhNode: a leaf (count > 0) holds items[first, first + count); an
// inner node's children are nodes first and first + 1.
struct RtNode {
    vec3 boundsMin;
    uint first;
    vec3 boundsMax;
    uint count;
};

// A child object placed in its parent's space by a rigid frame and a
// uniform scale (1 in a plant's graph; a field's plants are scaled).
struct RtInstance {
    vec4 rotation; // unit quaternion, xyz w
    vec3 position;
    uint object;
    float scale; // the child's metres per parent metre, > 0
    uint pad0;
    uint pad1;
    uint pad2;
};

// lsys::Primitive as GraphTracer holds it (a segment's radii already scaled
// for pixel-wide lines). Surfaces and polygons are the triangles
// [firstTriangle, firstTriangle + triangleCount): a surface's in its own
// space at scale 1, a polygon's in the space of the object drawing it.
struct RtPrimitive {
    vec4 rotation; // unit quaternion, xyz w
    vec3 position;
    uint kind;    // RAYTRACE_KIND_*
    float extent; // lsys::Primitive::length (GLSL reserves the name): a segment's length, a surface's scale
    float startRadius;
    float endRadius;
    uint material;
    uint firstTriangle;
    uint triangleCount;
    uint pad0;
    uint pad1;
};

// The w of each corner is free for the includer's cut-out test
// (RAYTRACE_CUT_OUT in raytrace_traverse.glsl): a field's leaf cards keep
// their texture coordinates there.
struct RtTriangle {
    vec4 a; // xyz, w free
    vec4 b;
    vec4 c;
};

// lsys::Ray.
struct RtRay {
    vec3 origin;
    float tMin;
    vec3 direction;
    float tMax;
};

// lsys::Hit: the normal unit, in the space of the traced ray; primitive is
// RAYTRACE_NO_HIT for a miss (then only stackUsed is meaningful).
struct RtHit {
    vec3 normal;
    float t;
    uint primitive;
    uint kind;
    uint material;
    uint stackUsed; // the most stack entries the ray's walk held: packGraph's bound is tested against it
};

struct RtTracePush {
    uint rayCount;
    uint query;    // RAYTRACE_QUERY_*
    uint rootNode; // the root object's root node; RAYTRACE_NO_NODE: the graph draws nothing
    uint pad;
};

#ifdef __cplusplus
} // namespace gpu
static_assert(sizeof(gpu::RtNode) == 16 * RAYTRACE_NODE_TEXELS);
static_assert(sizeof(gpu::RtInstance) == 16 * RAYTRACE_INSTANCE_TEXELS);
static_assert(sizeof(gpu::RtPrimitive) == 16 * RAYTRACE_PRIMITIVE_TEXELS);
static_assert(sizeof(gpu::RtTriangle) == 16 * RAYTRACE_TRIANGLE_TEXELS);
static_assert(sizeof(gpu::RtRay) == 32);
static_assert(sizeof(gpu::RtHit) == 32);
static_assert(sizeof(gpu::RtTracePush) == 16);
#endif

#endif
