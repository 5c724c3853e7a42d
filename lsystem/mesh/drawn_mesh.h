#pragma once
// The plant as the field draws it: a PlantAsset baked into triangle meshes
// at two levels of detail and two draw classes, the one bake that the
// renderer packs into its vertex pool (engine/scene/plant_models.cpp) and
// that `lsys export` writes by default (docs/EXPORT.md, "The drawn form").
//
// Bark segment chains become generalised cylinders whose ring sides follow
// their radius relative to the trunk; foliage segments (a two-sided
// material: needles, grass) become flat ribbons at least a minimum width
// wide; surfaces become leaf cards, quads whose leaf outline the renderer's
// fragment shader cuts (shaders/shared/leaf_outline.h); spheres and polygons are
// meshed as the turtle's. The reduced LOD drops twigs, merges ribbon runs and
// thins leaves and foliage chains.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lsystem/mesh/primitive_mesh.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys {

// How the renderer's fragment shader treats a vertex's surface; the values
// are shaders/shared/field_layouts.h's SURFACE_* (engine/scene/plant_models.cpp
// asserts that they agree).
enum class SurfaceKind : uint8_t {
    Bark = 0,     // opaque, bark streaks
    LeafCard = 1, // a card whose leaf outline the shader cuts (uv in [0,1]²)
    Blade = 2,    // an opaque two-sided blade, ribbon or polygon
};

// The draw classes with geometry, in the order of DRAW_BARK and DRAW_FOLIAGE.
enum class DrawClass : uint8_t { Bark = 0, Foliage = 1 };
inline constexpr size_t kDrawClassCount = 2;
// The mesh levels of detail, in the order of LOD_FULL and LOD_REDUCED.
enum class DrawnLod : uint8_t { Full = 0, Reduced = 1 };
inline constexpr size_t kDrawnLodCount = 2;

struct DrawnVertex {
    glm::vec3 position; // plant space
    glm::vec3 normal;
    glm::vec2 uv;
    uint32_t material; // into PlantAsset::materials (its albedo is the colour drawn)
    SurfaceKind kind;
    uint32_t joint; // the skeleton joint it moves with (the base, joint -1, moves with joint 0)
};

struct DrawnMesh {
    std::vector<DrawnVertex> vertices;
    std::vector<uint32_t> indices; // triangles, counter-clockwise seen from the outside (the card's normal)
};

using DrawnClasses = std::array<DrawnMesh, kDrawClassCount>; // [DrawClass]

// How leaf cards come out: as the quads the renderer draws and cuts, or as
// the mesh of the cut outline (exports, which carry no cut-out).
enum class LeafCards : uint8_t { Quads, Outlines };

struct DrawnOptions {
    // Ring sides of the trunk; thinner bark gets fewer, as barkSides says.
    // 8 is the renderer's.
    uint32_t trunkSides = 8;
    LeafCards leaves = LeafCards::Quads;
};

// What the exports bake (flat, instanced, and the box --height measures):
// the trunk with `trunkSides` ring sides, leaf cards as their outlines.
inline DrawnOptions exportedDrawnOptions(uint32_t trunkSides) { return {trunkSides, LeafCards::Outlines}; }

// What the bake measures on the whole plant: bark ring sides and LOD1's twig
// cut follow radii relative to the trunk, the minimum ribbon width the
// plant's extent. A part of a plant (an InstanceGraph object) baked with the
// whole plant's scale is baked as the whole plant bakes it.
struct DrawnScale {
    float trunkRadius = 0.0f;    // the widest bark segment radius
    float minRibbonWidth = 0.0f; // foliage ribbons are at least this wide
};
DrawnScale drawnScaleOf(const PlantAsset& asset);
// Of a plant given in parts (an InstanceGraph's objects' own primitives),
// `bounds` the whole plant's box.
DrawnScale drawnScaleOf(const std::vector<PlantAsset>& parts, const Bounds& bounds);

// One level of detail of the plant, per draw class.
DrawnClasses drawnLod(const PlantAsset& asset, DrawnLod lod, const DrawnScale& scale, const DrawnOptions& options = {});
// Both, full first: what the field's pool holds for the plant.
std::array<DrawnClasses, kDrawnLodCount> drawnLods(const PlantAsset& asset, const DrawnOptions& options = {});

// The full LOD with leaf outlines, as TriangleMeshes in plant space, one per
// entry of PlantAsset::materials (empty where a material is unused): the
// drawn form of the flat export.
std::vector<TriangleMesh> drawnMeshesByMaterial(const PlantAsset& asset, const DrawnScale& scale,
                                                const DrawnOptions& options);

// The leaf outline (shaders/shared/leaf_outline.h LEAF_HALF_WIDTH, mirrored about
// the midrib, without the serration and the petiole: they are a few
// hundredths of the card wide) as a triangle strip in uv space: the base
// point, kLeafOutlineRows − 1 rows of a left and a right point, the tip;
// counter-clockwise in uv.
inline constexpr uint32_t kLeafOutlineRows = 16;
struct LeafOutline {
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
};
const LeafOutline& leafOutline();
// Its vertex and index counts, for the exporters' memory estimates.
MeshSize leafOutlineSize();

// The outline placed on a card whose uv (0,0) corner is `origin` and whose u
// and v run along `across` and `along`, all vertices facing `normal`.
void appendLeafOutline(TriangleMesh& mesh, glm::vec3 origin, glm::vec3 across, glm::vec3 along, glm::vec3 normal);

} // namespace lsys
