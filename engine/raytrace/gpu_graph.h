// A GraphTracer (lsystem/raytrace/graph_tracer.h) packed into the arrays the
// GPU traversal reads (shaders/shared/raytrace_layouts.h, docs/RAYTRACING.md "The GPU
// traversal"): every object's BVH in one node array, leaf items that say
// whether they are a primitive or an instance, primitives and instances with
// their frames, and the triangles of surfaces and polygons. Pure CPU.
#pragma once

#include "shaders/shared/raytrace_layouts.h"

#include "lsystem/raytrace/graph_tracer.h"

#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace pf {

struct GpuGraph {
    std::vector<gpu::RtNode> nodes;    // object by object, each BVH's nodes in its own order
    std::vector<uint32_t> items;       // RAYTRACE_ITEM_INSTANCE | instance, or a primitive
    std::vector<uint32_t> objectRoots; // per object: its root node, or RAYTRACE_NO_NODE
    std::vector<gpu::RtInstance> instances;
    std::vector<gpu::RtPrimitive> primitives; // by InstanceGraph::primitives index
    std::vector<gpu::RtTriangle> triangles;
    uint32_t rootNode = RAYTRACE_NO_NODE; // of the root object
    uint32_t levels = 0;                  // instance levels a ray can be carried through, the root's counted
    uint32_t stackDepth = 0;              // stack entries the traversal can need at most
};

// What the fixed arrays of the GPU traversal cannot hold.
struct GpuGraphError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws GpuGraphError when a ray could be carried through more than
// RAYTRACE_MAX_LEVELS instance levels or need more than RAYTRACE_STACK_SIZE
// stack entries, or when an index does not fit its field.
GpuGraph packGraph(const lsys::GraphTracer& tracer);

// The parts both packers (packGraph, packFieldGraph) build graphs from.
// Nodes on the longest path from the BVH's root to a leaf; 0 without nodes.
uint32_t bvhHeight(const lsys::Bvh& bvh);
// Appends an object's BVH to `packed`: its nodes with global indices, its
// items in leaf order as `itemWords` packs them (by the index the BVH was
// built over: a primitive's index, or RAYTRACE_ITEM_INSTANCE | an instance).
// Returns its root node, RAYTRACE_NO_NODE when it has none.
uint32_t appendObjectBvh(GpuGraph& packed, const lsys::Bvh& bvh, std::span<const uint32_t> itemWords);
// Sets rootNode, levels and stackDepth from the root object's, and throws
// GpuGraphError when the traversal's fixed arrays cannot hold them.
void setRoot(GpuGraph& packed, uint32_t rootNode, uint32_t levels, uint32_t stackDepth);

} // namespace pf
