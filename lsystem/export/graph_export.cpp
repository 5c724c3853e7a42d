#include "lsystem/export/graph_export.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "lsystem/common/output_file.h"
#include "lsystem/export/export_detail.h"
#include "lsystem/export/gltf_builder.h"
#include "lsystem/mesh/drawn_mesh.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/turtle/turtle_builder.h"

namespace lsys {
namespace {

using export_detail::GltfBuilder;

// The primitives `object` places directly, in its local space, as a
// PlantAsset: a segment's parent is its local joint when the object drew that
// segment itself (so generalised cylinders chain within the object) and the
// base otherwise. The builder also gives the materials the turtle would.
PlantAsset directPrimitives(const InstanceGraph& graph, uint32_t object, const SurfaceLibrary& surfaces) {
    PlantAssetBuilder builder(surfaces, graph.look);
    std::unordered_map<JointRef, int32_t> localJoint;
    const auto local = [&](JointRef ref) {
        const auto found = localJoint.find(ref);
        return found == localJoint.end() ? -1 : found->second;
    };
    for (const GraphItem& item : graph.itemsOf(object)) {
        if (item.kind != GraphItem::Kind::Primitive) continue;
        const GraphPrimitive& p = graph.primitives[item.index];
        switch (p.kind) {
        case PrimitiveKind::Segment:
            localJoint[p.joint] = builder.addSegment(p.frame, p.length, p.startRadius, p.endRadius, p.material,
                                                     local(p.parentJoint), p.stiffness);
            break;
        case PrimitiveKind::Sphere: builder.addSphere(p.frame, p.startRadius, p.material, -1); break;
        case PrimitiveKind::Surface:
            builder.addSurface(graph.surfaceNames[p.shape], p.frame, p.length, p.material, -1);
            break;
        case PrimitiveKind::Polygon:
            builder.addPolygon(p.frame, graph.polygons[p.shape].outline, p.material, -1);
            break;
        }
    }
    PlantAsset direct = builder.finish();
    if (graph.pixelLines) scaleLineRadii(direct, worldPerPixel(graph.objects[graph.root].bounds));
    return direct;
}

// Every object's table holds the palette up to the largest index it uses, so
// the longest table with the two-sided flags of all is the flat plant's.
void mergeMaterials(std::vector<Material>& into, const std::vector<Material>& from) {
    if (from.size() > into.size()) into.resize(from.size());
    for (size_t i = 0; i < from.size(); ++i) {
        const bool twoSided = into[i].twoSided || from[i].twoSided;
        if (into[i].name.empty()) into[i] = from[i];
        into[i].twoSided = twoSided;
    }
}

// The instances that get a node: those whose subtree draws something. A
// context-sensitive word of letters the turtle ignores can have millions of
// instance paths and no primitive.
bool needsNode(const InstanceGraph& graph, const GraphItem& item) {
    return item.kind == GraphItem::Kind::Instance && graph.objects[graph.instances[item.index].object].primitives > 0;
}

// Per object: 1 + the counts of the objects it instances (children come
// before parents), saturating.
std::vector<uint64_t> nodeCounts(const InstanceGraph& graph) {
    std::vector<uint64_t> counts(graph.objects.size(), 1);
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        for (const GraphItem& item : graph.itemsOf(object)) {
            if (!needsNode(graph, item)) continue;
            const uint64_t child = counts[graph.instances[item.index].object];
            if (__builtin_add_overflow(counts[object], child, &counts[object])) counts[object] = UINT64_MAX;
        }
    }
    return counts;
}

// The node of an instance of `object` and, below it, those of its instances;
// translations times `scale` (GraphExportOptions::scale).
void addInstanceNodes(GltfBuilder& builder, const InstanceGraph& graph, const std::vector<int>& meshOf, uint32_t object,
                      int node, float scale) {
    for (const GraphItem& item : graph.itemsOf(object)) {
        if (!needsNode(graph, item)) continue;
        const GraphInstance& instance = graph.instances[item.index];
        const Frame frame{instance.frame.position * scale, instance.frame.rotation};
        const int child =
            builder.addNode("object_" + std::to_string(instance.object), node, frame, meshOf[instance.object]);
        addInstanceNodes(builder, graph, meshOf, instance.object, child, scale);
    }
}

void writeGraphGltf(const InstanceGraph& graph, const SurfaceLibrary& surfaces, std::ostream& out,
                    const GraphExportOptions& options, bool binary, GraphExportSummary& summary) {
    std::vector<PlantAsset> directs;
    std::vector<Material> materials;
    for (uint32_t object = 0; object < graph.objects.size(); ++object) {
        PlantAsset& direct = directs.emplace_back(directPrimitives(graph, object, surfaces));
        if (options.scale != 1.0f) scalePlant(direct, options.scale);
        mergeMaterials(materials, direct.materials);
    }
    std::vector<std::vector<TriangleMesh>> meshes;
    if (options.geometry == ExportGeometry::Drawn) {
        Bounds box;
        if (!graph.objects.empty())
            box = {graph.objects[graph.root].bounds.min * options.scale,
                   graph.objects[graph.root].bounds.max * options.scale};
        const DrawnScale scale = drawnScaleOf(directs, box);
        const DrawnOptions drawn = exportedDrawnOptions(options.detail.segmentSides);
        for (const PlantAsset& direct : directs) meshes.push_back(drawnMeshesByMaterial(direct, scale, drawn));
    } else {
        for (const PlantAsset& direct : directs)
            meshes.push_back(meshesByMaterial(direct, options.segments, options.detail));
    }
    directs.clear();
    GltfBuilder builder(materials);
    std::vector<int> meshOf;
    for (uint32_t object = 0; object < graph.objects.size(); ++object)
        meshOf.push_back(builder.addMesh(meshes[object], "object_" + std::to_string(object)));
    summary.meshes = builder.model.meshes.size();
    if (!graph.objects.empty()) {
        // The root object is the plant node itself: placed at the plant's start.
        builder.model.nodes[GltfBuilder::kRoot].mesh = meshOf[graph.root];
        addInstanceNodes(builder, graph, meshOf, graph.root, GltfBuilder::kRoot, options.scale);
    }
    summary.nodes = builder.model.nodes.size();
    builder.write(out, binary);
}

// Every object's direct primitives as meshes (drawable or not: a bound; the
// drawn form at most the frusta's plus each leaf's outline).
MeshSize graphMeshSize(const InstanceGraph& graph, const SurfaceLibrary& surfaces, const GraphExportOptions& options) {
    MeshSize total;
    for (const GraphPrimitive& p : graph.primitives) {
        if (p.kind == PrimitiveKind::Surface && options.geometry == ExportGeometry::Drawn) total.add(leafOutlineSize());
        MeshSize shape;
        if (p.kind == PrimitiveKind::Surface) {
            const SurfaceMesh& surface = surfaceOfLook(graph.look, surfaces, graph.surfaceNames[p.shape]);
            shape = {surface.positions.size(), surface.indices.size()};
        }
        if (p.kind == PrimitiveKind::Polygon) shape.vertices = graph.polygons[p.shape].outline.size();
        total.add(primitiveMeshSize(p.kind, shape, options.detail));
    }
    return total;
}

} // namespace

uint64_t graphExportNodeCount(const InstanceGraph& graph) {
    return graph.objects.empty() ? 1 : nodeCounts(graph)[graph.root];
}

GraphExportSummary exportInstanceGraph(const InstanceGraph& graph, const SurfaceLibrary& surfaces,
                                       const std::filesystem::path& path, const GraphExportOptions& options) {
    using namespace export_detail;
    GraphExportSummary summary;
    try {
        const std::string extension = lowercaseExtension(path);
        if (extension != ".gltf" && extension != ".glb")
            throw std::runtime_error("unknown extension '" + extension +
                                     "' for the instanced form (expected .gltf or .glb; OBJ is always flat)");
        const uint64_t nodes = graphExportNodeCount(graph);
        if (nodes > options.maxNodes)
            throw std::runtime_error("the instanced form would write " + std::to_string(nodes) +
                                     " glTF nodes (one per instance path), more than the budget of " +
                                     std::to_string(options.maxNodes) +
                                     "; export the flat form (--flat) or derive fewer steps");
        need(options.memory, "export", gltfBytes(graphMeshSize(graph, surfaces, options), nodes, extension == ".glb"));
        OutputFile file(path);
        writeGraphGltf(graph, surfaces, file.stream(), options, extension == ".glb", summary);
        file.commit();
    } catch (const std::exception&) {
        rethrowNaming(path);
    }
    return summary;
}

} // namespace lsys
