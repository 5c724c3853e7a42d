#pragma once
// Triangle meshes for the primitives of a PlantAsset, shared by the exporter
// and the renderer. Each function returns the mesh in the primitive's own
// space (local +Y along the segment, as for a Frame) unless it says otherwise.
//
// Topology never depends on radii or lengths: a cone whose tip radius is 0
// keeps its degenerate tip triangles, so one unit mesh can serve every
// segment and the counts below hold for every input.

#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lsystem/turtle/plant_asset.h"

namespace lsys {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; // unit length, one per position
    std::vector<glm::vec2> uvs;     // one per position; see each function for the mapping
    std::vector<uint32_t> indices;  // triangles, counter-clockwise seen from the outside

    uint32_t vertexCount() const { return uint32_t(positions.size()); }
    uint32_t triangleCount() const { return uint32_t(indices.size() / 3); }
    // Appends `mesh` moved by the rigid-or-uniformly-scaled `transform`.
    void append(const TriangleMesh& mesh, const glm::mat4& transform);
};

// Sides of segment and generalised-cylinder rings, and sphere tessellation.
// Smaller values than the minimums are raised to them.
struct MeshDetail {
    uint32_t segmentSides = 8;  // at least 3
    bool segmentCaps = true;    // close both ends of a segment or a chain
    uint32_t sphereSlices = 12; // around, at least 3
    uint32_t sphereStacks = 8;  // pole to pole, at least 2
};

// Cone frustum from radius `startRadius` at y = 0 to `endRadius` at y = length.
// u goes once around, v is the distance along the axis in metres (bark tiles
// at the same size on every segment). Sides: 2·(sides+1) vertices (the seam
// is duplicated for u), 2·sides triangles; caps add (sides+1) vertices and
// `sides` triangles each.
TriangleMesh segmentMesh(float length, float startRadius, float endRadius, const MeshDetail& detail);

// UV sphere of `radius` about the origin, poles on ±Y: (slices+1)·(stacks+1)
// vertices, 2·slices·(stacks−1) triangles (one per pole quad).
TriangleMesh sphereMesh(float radius, const MeshDetail& detail);

// A `{ . }` outline, possibly non-convex, roughly planar, in any space:
// triangulated by ear clipping in its best-fit (Newell) plane, in that same
// space. Repeated consecutive points are dropped; n distinct points give n
// vertices and n−2 triangles; fewer than 3, or an outline with no area,
// give an empty mesh. Normals are
// the plane normal, on the side from which the outline turns
// counter-clockwise; uv is the position in the plane in metres.
TriangleMesh polygonMesh(const std::vector<glm::vec3>& outline);

// A predefined surface as a TriangleMesh: missing normals are computed from
// the faces, missing uvs are zero.
TriangleMesh surfaceMesh(const SurfaceMesh& surface);

// Segments drawn one after another along one axis: each continues the
// previous from its tip (see segmentChains).
struct SegmentChain {
    std::vector<uint32_t> primitives; // indices into PlantAsset::primitives, base first
};

// Splits the asset's segments into chains. A segment continues its parent
// joint's segment when it starts at that segment's tip, has the same
// material, and of all such children its heading turns least from the
// parent's (less than 90°); at a branch point the axis therefore continues
// and the lateral branches start chains of their own. Every segment is in
// exactly one chain; chains are ordered by their first segment.
std::vector<SegmentChain> segmentChains(const PlantAsset& asset);

// A generalised cylinder in plant space: one ring at the chain's base, one at
// every joint between two segments, one at the tip. An inner ring lies in the
// plane halfway between the incoming and outgoing headings and is shared by
// both segments, so the tube bends without gaps; it is stretched along the
// bend by 1/cos(half the turn) (at most 2×) so the tube keeps its thickness.
// Its radius is the mean of the two segments' radii there. Ring i+1 is the
// previous one carried along the axis without twist. For k segments:
// (k+1)·(sides+1) vertices, 2·k·sides triangles, plus caps as for
// segmentMesh. u and v as for segmentMesh, v summed along the chain.
TriangleMesh generalizedCylinderMesh(const PlantAsset& asset, const SegmentChain& chain, const MeshDetail& detail);

// How segments become triangles: one closed frustum each (instanced
// cylinders and cones: cheap, small gaps where a stem bends), or generalised
// cylinders along each SegmentChain (no gaps; not shareable between plants).
enum class SegmentGeometry : uint8_t { Frusta, GeneralizedCylinders };

// One primitive's mesh in plant space (its frame applied; a surface scaled
// by `length`). Throws std::out_of_range for a shape index outside the asset.
TriangleMesh bakedPrimitiveMesh(const PlantAsset& asset, const Primitive& primitive, const MeshDetail& detail);

// Every drawable primitive baked in plant space, one mesh per entry of
// PlantAsset::materials (empty where a material is unused).
std::vector<TriangleMesh> meshesByMaterial(const PlantAsset& asset, SegmentGeometry segments, const MeshDetail& detail);

// Only the generalised cylinders of every SegmentChain, baked as above; a
// chain has its segments' material (chains never mix materials).
std::vector<TriangleMesh> generalizedCylindersByMaterial(const PlantAsset& asset, const MeshDetail& detail);

// The size of meshes counted without building them; bytes() as TriangleMesh
// holds them (position, normal and uv a vertex, 32-bit indices), saturating.
struct MeshSize {
    uint64_t vertices = 0;
    uint64_t indices = 0;
    uint64_t bytes() const;
    void add(const MeshSize& other);
};
// Of one primitive's mesh; `shape` is its surface's mesh or polygon's
// outline length as {vertices, indices} (polygons: the outline's points).
MeshSize primitiveMeshSize(PrimitiveKind kind, const MeshSize& shape, const MeshDetail& detail);
// Of meshesByMaterial(asset, segments, detail) together; with generalised
// cylinders at most that (a tube of k segments has fewer vertices and
// triangles than k frusta with caps).
MeshSize bakedMeshSize(const PlantAsset& asset, const MeshDetail& detail);

// Whether a primitive has any area to draw: segments with a length and a
// radius, spheres with a radius, surfaces with a scale. Polygons always count
// (a degenerate outline gives an empty mesh). The exporter skips the rest.
bool isDrawable(const Primitive& primitive);

// The primitive's frame as a matrix (rotation, then translation).
glm::mat4 frameMatrix(const Frame& frame);

} // namespace lsys
