#include "engine/raytrace/gpu_graph.h"

#include <algorithm>
#include <string>

namespace pf {
namespace {

static_assert(uint32_t(lsys::PrimitiveKind::Segment) == RAYTRACE_KIND_SEGMENT);
static_assert(uint32_t(lsys::PrimitiveKind::Sphere) == RAYTRACE_KIND_SPHERE);
static_assert(uint32_t(lsys::PrimitiveKind::Surface) == RAYTRACE_KIND_SURFACE);
static_assert(uint32_t(lsys::PrimitiveKind::Polygon) == RAYTRACE_KIND_POLYGON);
static_assert(uint32_t(lsys::HitQuery::Closest) == RAYTRACE_QUERY_CLOSEST);
static_assert(uint32_t(lsys::HitQuery::Any) == RAYTRACE_QUERY_ANY);

glm::vec4 quatAsVec4(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

struct TriangleRange {
    uint32_t first = 0;
    uint32_t count = 0;
};

// Appends the meshes' triangles; the range of each mesh.
std::vector<TriangleRange> appendTriangles(std::vector<gpu::RtTriangle>& triangles,
                                           const std::vector<lsys::TriangleMesh>& meshes) {
    std::vector<TriangleRange> ranges;
    for (const lsys::TriangleMesh& mesh : meshes) {
        ranges.push_back({uint32_t(triangles.size()), mesh.triangleCount()});
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
            triangles.push_back({glm::vec4(mesh.positions[mesh.indices[i]], 0.0f),
                                 glm::vec4(mesh.positions[mesh.indices[i + 1]], 0.0f),
                                 glm::vec4(mesh.positions[mesh.indices[i + 2]], 0.0f)});
    }
    return ranges;
}

} // namespace

uint32_t bvhHeight(const lsys::Bvh& bvh) {
    // Children always follow their parent in Bvh::nodes (buildBvh appends them).
    std::vector<uint32_t> height(bvh.nodes.size(), 1);
    for (size_t i = bvh.nodes.size(); i-- > 0;) {
        const lsys::BvhNode& node = bvh.nodes[i];
        if (node.count == 0) height[i] = 1 + std::max(height[node.first], height[node.first + 1]);
    }
    return height.empty() ? 0 : height[0];
}

uint32_t appendObjectBvh(GpuGraph& packed, const lsys::Bvh& bvh, std::span<const uint32_t> itemWords) {
    const auto nodeBase = uint32_t(packed.nodes.size()), itemBase = uint32_t(packed.items.size());
    for (const lsys::BvhNode& node : bvh.nodes)
        packed.nodes.push_back({node.bounds.min, node.count > 0 ? itemBase + node.first : nodeBase + node.first,
                                node.bounds.max, node.count});
    for (uint32_t i : bvh.items) packed.items.push_back(itemWords[i]);
    if (packed.nodes.size() >= RAYTRACE_NO_NODE) throw GpuGraphError("the graph has more BVH nodes than 2^32 - 1");
    return bvh.nodes.empty() ? RAYTRACE_NO_NODE : nodeBase;
}

void setRoot(GpuGraph& packed, uint32_t rootNode, uint32_t levels, uint32_t stackDepth) {
    packed.rootNode = rootNode;
    packed.levels = levels;
    packed.stackDepth = stackDepth;
    if (levels > RAYTRACE_MAX_LEVELS)
        throw GpuGraphError("a ray can be carried through " + std::to_string(levels) +
                            " levels of instances; the GPU traversal holds " + std::to_string(RAYTRACE_MAX_LEVELS) +
                            " (RAYTRACE_MAX_LEVELS, shaders/shared/raytrace_layouts.h)");
    if (stackDepth > RAYTRACE_STACK_SIZE)
        throw GpuGraphError("tracing the graph can need " + std::to_string(stackDepth) +
                            " stack entries; the GPU traversal holds " + std::to_string(RAYTRACE_STACK_SIZE) +
                            " (RAYTRACE_STACK_SIZE, shaders/shared/raytrace_layouts.h)");
}

GpuGraph packGraph(const lsys::GraphTracer& tracer) {
    const lsys::InstanceGraph& graph = *tracer.graph;
    if (graph.primitives.size() >= RAYTRACE_ITEM_INSTANCE || graph.instances.size() >= RAYTRACE_ITEM_INSTANCE)
        throw GpuGraphError("the graph has more primitives or instances than a GPU item can index (2^31)");
    GpuGraph packed;

    const std::vector<TriangleRange> surfaceTriangles =
        appendTriangles(packed.triangles, tracer.shapes.surfaces.meshes);
    const std::vector<TriangleRange> polygonTriangles =
        appendTriangles(packed.triangles, tracer.shapes.polygons.meshes);
    packed.primitives.reserve(tracer.primitives.size());
    for (const lsys::Primitive& p : tracer.primitives) {
        TriangleRange triangles;
        if (p.kind == lsys::PrimitiveKind::Surface) triangles = surfaceTriangles.at(p.shape);
        if (p.kind == lsys::PrimitiveKind::Polygon) triangles = polygonTriangles.at(p.shape);
        packed.primitives.push_back({quatAsVec4(p.frame.rotation), p.frame.position, uint32_t(p.kind), p.length,
                                     p.startRadius, p.endRadius, p.material, triangles.first, triangles.count, 0, 0});
    }
    for (const lsys::GraphInstance& instance : graph.instances)
        packed.instances.push_back(
            {quatAsVec4(instance.frame.rotation), instance.frame.position, instance.object, 1.0f, 0, 0, 0});

    // Per object, children first: the levels and stack entries a ray entering
    // it can need. Walking an object's BVH keeps at most one entry per node on
    // the path to the current one (the farther children left for later, and
    // the rest of a leaf whose instance it descends into), so an object needs
    // its BVH's height and, below a leaf, what its deepest child needs.
    std::vector<uint32_t> levels(graph.objects.size(), 0), stackDepth(graph.objects.size(), 0);
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        const lsys::Bvh& bvh = tracer.objectBvhs[object];
        const std::span<const lsys::GraphItem> items = graph.itemsOf(object);
        std::vector<uint32_t> itemWords(items.size());
        for (size_t i = 0; i < items.size(); ++i)
            itemWords[i] = items[i].kind == lsys::GraphItem::Kind::Primitive ? items[i].index
                                                                             : RAYTRACE_ITEM_INSTANCE | items[i].index;
        packed.objectRoots.push_back(appendObjectBvh(packed, bvh, itemWords));
        uint32_t childLevels = 0, childStack = 0;
        for (uint32_t i : bvh.items) {
            if (items[i].kind == lsys::GraphItem::Kind::Primitive) continue;
            const uint32_t child = graph.instances[items[i].index].object;
            childLevels = std::max(childLevels, levels[child]);
            childStack = std::max(childStack, stackDepth[child]);
        }
        if (bvh.nodes.empty()) continue;
        levels[object] = 1 + childLevels;
        stackDepth[object] = bvhHeight(bvh) + std::max(1u, childStack);
    }
    if (!graph.objects.empty())
        setRoot(packed, packed.objectRoots[graph.root], levels[graph.root], stackDepth[graph.root]);
    return packed;
}

} // namespace pf
