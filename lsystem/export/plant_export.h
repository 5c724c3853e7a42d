#pragma once
// Writes a PlantAsset as glTF 2.0 (.gltf with the buffer embedded as base64,
// or .glb) or Wavefront OBJ (.obj plus a .mtl beside it), chosen by the
// file's extension, in the flat form: every primitive baked in plant space,
// by default as the field draws it (lsystem/mesh/drawn_mesh.h).
// The instanced form, which keeps the InstanceGraph's shared subtrees, is
// lsystem/export/graph_export.h. docs/EXPORT.md describes what each form contains.

#include <filesystem>
#include <vector>

#include "lsystem/common/memory_budget.h"
#include "lsystem/mesh/primitive_mesh.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys {

// What the flat form's meshes are: the plant as the field draws it up close
// (drawnMeshesByMaterial: bark tubes, foliage ribbons, leaf outlines), or the
// turtle's primitives (meshesByMaterial, segments as `segments` says).
enum class ExportGeometry : uint8_t { Drawn, Turtle };

struct ExportOptions {
    ExportGeometry geometry = ExportGeometry::Drawn;
    SegmentGeometry segments = SegmentGeometry::Frusta; // the turtle's geometry only
    // Turtle: every segment's ring sides and the spheres'. Drawn: the trunk's
    // ring sides (thinner bark gets fewer, DrawnOptions::trunkSides).
    MeshDetail detail;
    bool skeleton = true; // glTF: one node per Joint, nested as Joint::parent says
    // > 0: the meshes, baked once, are scaled uniformly about the plant's
    // base (the origin) so their y extent is `height`; the skeleton with them.
    float height = 0.0f;
    // What the writer would hold at once, estimated from the primitives'
    // vertex and index counts before any mesh is built (export_detail.h).
    MemoryBudget memory = machineMemoryBudget();
};

// Throws std::runtime_error naming `path` when the extension is not .gltf,
// .glb or .obj, when the asset is inconsistent (a material or shape index out
// of range, a joint cycle), or when a file cannot be written; throws
// MemoryBudgetError (stage "export") past options.memory, before writing. Each file is
// written to PATH.partial and renamed into place, so a failure leaves no
// file behind and never a half-written one.
// With options.height, a plant whose meshes have no y extent is refused
// likewise. Returns the scale applied (1 without options.height).
float exportPlant(const PlantAsset& asset, const std::filesystem::path& path, const ExportOptions& options = {});

// The files exportPlant writes for `path`: the file itself, and for .obj the
// .mtl beside it, so a caller can check them all before the work.
std::vector<std::filesystem::path> exportedFiles(const std::filesystem::path& path);

// The box of every vertex meshesByMaterial bakes for the turtle's geometry,
// each primitive or segment chain built and dropped in turn, where
// PlantAsset::bounds holds the turtle's round geometry (outside rings of few
// sides) padded by the widest pixel-wide line. `lsys export --instanced
// --height` measures the flattened graph with it.
Bounds bakedBounds(const PlantAsset& asset, SegmentGeometry segments, const MeshDetail& detail);

// The uniform scale that makes `bounds` `height` tall (their y extent). 0
// when the bounds are empty or have no height, which no scale can stretch.
float heightScale(const Bounds& bounds, float height);

// Scales the plant uniformly by `factor` (> 0) about its base (the origin), so that
// every form exported afterwards is `factor` times as large: primitive frames
// and sizes, polygon outlines, joints' rest frames and sizes, bounds. Joint
// stiffness is not exported and is left as it is.
void scalePlant(PlantAsset& asset, float factor);

} // namespace lsys
