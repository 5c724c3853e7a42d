// Walking an InstanceGraph: flattening it into a PlantAsset, its materials and its sizes.

#include <algorithm>
#include <string>

#include "lsystem/common/error.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/instancing/instance_graph_lazy.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/turtle/turtle_builder.h"

namespace lsys {

namespace {

// Replays the objects' primitives through a PlantAssetBuilder in drawing
// order, so joints, shapes, bounds and materials come out as the turtle's.
class Flattener {
public:
    Flattener(const InstanceGraph& graph, const SurfaceLibrary& surfaces) : graph_(graph), out_(surfaces, graph.look) {}

    PlantAsset run() {
        if (!graph_.objects.empty()) walk(graph_.root, Frame{}, -1);
        PlantAsset plant = out_.finish();
        if (graph_.pixelLines) widenPixelLines(plant);
        return plant;
    }

private:
    void walk(uint32_t object, const Frame& frame, int32_t entryJoint) {
        const int64_t base = joints_; // the subtree's first joint
        auto global = [&](JointRef ref) { return ref == kEntryJoint ? entryJoint : static_cast<int32_t>(base + ref); };
        for (const GraphItem& item : graph_.itemsOf(object)) {
            if (item.kind == GraphItem::Kind::Instance) {
                const GraphInstance& instance = graph_.instances[item.index];
                walk(instance.object, compose(frame, instance.frame), global(instance.entryJoint));
                continue;
            }
            const GraphPrimitive& p = graph_.primitives[item.index];
            const Frame placed = compose(frame, p.frame);
            switch (p.kind) {
            case PrimitiveKind::Segment:
                out_.addSegment(placed, p.length, p.startRadius, p.endRadius, p.material, global(p.parentJoint),
                                p.stiffness);
                ++joints_;
                break;
            case PrimitiveKind::Sphere: out_.addSphere(placed, p.startRadius, p.material, global(p.joint)); break;
            case PrimitiveKind::Surface:
                out_.addSurface(graph_.surfaceNames[p.shape], placed, p.length, p.material, global(p.joint));
                break;
            case PrimitiveKind::Polygon: {
                std::vector<glm::vec3> outline;
                for (const glm::vec3& v : graph_.polygons[p.shape].outline)
                    outline.push_back(frame.position + frame.rotation * v);
                out_.addPolygon(placed, std::move(outline), p.material, global(p.joint));
                break;
            }
            }
        }
    }

    const InstanceGraph& graph_;
    PlantAssetBuilder out_;
    int64_t joints_ = 0;
};

template <typename T>
size_t bytesOf(const std::vector<T>& v) {
    return v.size() * sizeof(T);
}

// The materials primitives use, and which of them a surface or polygon uses
// (two-sided, as the turtle makes them).
struct MaterialUse {
    size_t used = 0;
    std::vector<bool> twoSided;
};

void noteMaterials(MaterialUse& use, const std::vector<GraphPrimitive>& primitives) {
    for (const GraphPrimitive& primitive : primitives) {
        use.used = std::max<size_t>(use.used, primitive.material + 1);
        if (primitive.kind != PrimitiveKind::Surface && primitive.kind != PrimitiveKind::Polygon) continue;
        if (use.twoSided.size() <= primitive.material) use.twoSided.resize(primitive.material + 1);
        use.twoSided[primitive.material] = true;
    }
}

} // namespace

Frame compose(const Frame& parent, const Frame& local) {
    return {parent.position + parent.rotation * local.position, glm::normalize(parent.rotation * local.rotation)};
}

Bounds transformed(const Bounds& local, const Frame& frame) {
    Bounds bounds;
    if (local.empty()) return bounds;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{corner & 1 ? local.max.x : local.min.x, corner & 2 ? local.max.y : local.min.y,
                          corner & 4 ? local.max.z : local.min.z};
        bounds.extend(frame.position + frame.rotation * p);
    }
    return bounds;
}

PlantAsset flatten(const InstanceGraph& graph, const SurfaceLibrary& surfaces, uint64_t maxPrimitives) {
    if (!graph.objects.empty() && graph.objects[graph.root].primitives > maxPrimitives)
        throw DerivationError("flattening the instance graph would give " +
                              std::to_string(graph.objects[graph.root].primitives) +
                              " primitives, more than the budget of " + std::to_string(maxPrimitives));
    return Flattener(graph, surfaces).run();
}

std::vector<Material> materialsOf(const InstanceGraph& graph) {
    MaterialUse use;
    noteMaterials(use, graph.primitives);
    return materialTable(graph.look, use.used, use.twoSided);
}

std::vector<Material> materialsOf(const LazyInstanceGraph& graph) {
    MaterialUse use;
    for (uint32_t object = 0; object < graph.graph.objects.size(); ++object)
        noteMaterials(use, expandObject(graph, object).primitives);
    return materialTable(graph.graph.look, use.used, use.twoSided);
}

std::vector<NamedInstanceStat> namedStats(const InstanceGraphStats& stats) {
    return {{"primitives", stats.primitives},
            {"joints", stats.joints},
            {"nodes", uint64_t(stats.nodes)},
            {"objects", uint64_t(stats.objects)},
            {"instances", stats.instances},
            {"compression", stats.compression()},
            {"bytes_graph", uint64_t(stats.bytesGraph)},
            {"bytes_flat", uint64_t(stats.bytesFlat)}};
}

InstanceGraphStats instanceGraphStats(const InstanceGraph& graph) {
    InstanceGraphStats stats;
    stats.nodes = graph.nodes;
    stats.objects = graph.objects.size();
    stats.instances = graph.instances.size() + graph.primitives.size();
    if (!graph.objects.empty()) {
        stats.primitives = graph.objects[graph.root].primitives;
        stats.joints = graph.objects[graph.root].joints;
    }
    stats.bytesGraph = sizeof(InstanceGraph) + bytesOf(graph.objects) + bytesOf(graph.items) +
                       bytesOf(graph.primitives) + bytesOf(graph.instances) + bytesOf(graph.polygons) +
                       bytesOf(graph.surfaceNames);
    for (const PolygonShape& polygon : graph.polygons) stats.bytesGraph += bytesOf(polygon.outline);
    for (const std::string& name : graph.surfaceNames) stats.bytesGraph += name.size();
    if (__builtin_mul_overflow(stats.primitives, sizeof(Primitive), &stats.bytesFlat)) stats.bytesFlat = SIZE_MAX;
    return stats;
}

} // namespace lsys
