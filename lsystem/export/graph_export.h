#pragma once
// Writes an InstanceGraph as glTF 2.0 keeping its shared subtrees (the
// instanced form of docs/EXPORT.md): each object becomes one glTF mesh of the
// primitives it places directly, in its local space, and each instance a node
// with the instance's transform whose mesh is its object's and whose children
// are the object's own instances. The node tree mirrors the graph (less the
// subtrees that draw nothing), and every instance of an object shares the
// object's mesh.

#include <cstdint>
#include <filesystem>

#include "lsystem/common/memory_budget.h"
#include "lsystem/export/plant_export.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/mesh/primitive_mesh.h"
#include "lsystem/turtle/surfaces.h"

namespace lsys {

struct GraphExportOptions {
    // Drawn: each object's own primitives as the field draws them
    // (drawn_mesh.h), with the whole plant's trunk radius and the graph's
    // box for the ring sides and the minimum ribbon width. Turtle: as
    // `segments` says. Generalised cylinders and the drawn form's bark
    // tubes follow the segments an object draws itself; chains end where an
    // instance starts (a bent tube is not shareable).
    ExportGeometry geometry = ExportGeometry::Drawn;
    SegmentGeometry segments = SegmentGeometry::Frusta;
    MeshDetail detail; // as ExportOptions::detail
    // One node per path of instances from the root: a deep plant has
    // exponentially many, so past this the export is refused.
    uint64_t maxNodes = 1'000'000;
    // Uniform scale (> 0) about the plant's base baked into what is written:
    // each object's primitives as scalePlant scales them, and the instances'
    // translations, so nodes stay rigid. (The graph itself is not scaled: with
    // pixel-wide lines its radii are in pixels until written.)
    float scale = 1.0f;
    // What the writer would hold at once, from the objects' primitives and
    // the node count, before any mesh is built (stage "export").
    MemoryBudget memory = machineMemoryBudget();
};

struct GraphExportSummary {
    size_t meshes = 0;  // objects whose direct primitives have triangles
    uint64_t nodes = 0; // the root's and one per instance path that draws something
};

// The number of glTF nodes the graph's export writes, from memoised counts
// (saturating at UINT64_MAX): 1 for the root object plus, recursively, one per
// instance whose subtree draws a primitive (the others would be empty nodes).
uint64_t graphExportNodeCount(const InstanceGraph& graph);

// Writes `path` (.gltf with the buffer embedded, or .glb) through PATH.partial
// as exportPlant does; `surfaces` resolves the graph's surface names (as for
// flatten()). Throws std::runtime_error starting "export PATH:" for another
// extension (OBJ cannot share meshes: flatten and use exportPlant), for a
// graph past options.maxNodes, a surface the library lacks, or a file that
// cannot be written.
GraphExportSummary exportInstanceGraph(const InstanceGraph& graph, const SurfaceLibrary& surfaces,
                                       const std::filesystem::path& path, const GraphExportOptions& options = {});

} // namespace lsys
