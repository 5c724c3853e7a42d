#pragma once
// One primitive under a ray, whichever plant form holds it: its bounds and
// its exact test (docs/RAYTRACING.md, "Primitive tests"). Surfaces and
// polygons are traced as the triangles the exporter meshes them with
// (surfaceMesh, polygonMesh); segments and spheres exactly.

#include <cstdint>
#include <vector>

#include "lsystem/instancing/instance_graph.h"
#include "lsystem/mesh/primitive_mesh.h"
#include "lsystem/raytrace/ray.h"
#include "lsystem/turtle/plant_asset.h"
#include "lsystem/turtle/surfaces.h"

namespace lsys {

// Triangle meshes by Primitive::shape, each with its box.
struct TracedMeshes {
    std::vector<TriangleMesh> meshes;
    std::vector<Bounds> bounds;
};

// The triangles of a plant's surfaces and polygons: two lists, as a lazily
// expanded graph keeps its surfaces once and each object's polygons with it.
struct TracedShapes {
    TracedMeshes surfaces; // in the surface's own space, at scale 1
    TracedMeshes polygons; // in the space of the outline (a flat plant's, or the drawing object's)
};

TracedShapes tracedShapesOf(const PlantAsset& plant);
TracedMeshes tracedPolygons(const std::vector<PolygonShape>& polygons);
// The graph's surfaces by name, looked up as flattening does (the grammar's
// look first, then `surfaces`); throws SurfaceError for one that is missing.
TracedShapes tracedShapesOf(const InstanceGraph& graph, const SurfaceLibrary& surfaces);

// A graph primitive as the flat record the tests below take (joint left at
// -1), a segment's radii times `lineScale` (the world size of a pixel for a
// graph of pixel-wide lines, 1 otherwise).
Primitive tracedPrimitive(const GraphPrimitive& primitive, float lineScale);

// The ray in the space of a frame given in the ray's space (its position,
// and the inverse of its rotation): rigid, so the same t and the same
// [tMin, tMax].
Ray rayInFrame(const Ray& ray, const glm::vec3& position, const glm::quat& toLocal);

// The box around what the primitive draws, in the space its frame is given
// in, widened by a few ulps of its size so a hit on a face of the box is
// never culled by the box test's rounding. Empty when it draws nothing
// (isDrawable) or its shape has no triangles.
Bounds tracedBounds(const Primitive& primitive, const TracedMeshes& surfaces, const TracedMeshes& polygons);

// Tests primitive number `index` against the ray (in the space of the
// primitive's frame). On a hit nearer than ray.tMax it sets `hit` (the
// normal in the ray's space), lowers ray.tMax to it and returns true.
bool tracePrimitive(const Primitive& primitive, uint32_t index, const TracedMeshes& surfaces,
                    const TracedMeshes& polygons, Ray& ray, Hit& hit);
// The same with the inverse of the primitive's rotation computed once
// beforehand (a tracer that tests each primitive many times keeps it).
bool tracePrimitive(const Primitive& primitive, const glm::quat& toLocal, uint32_t index, const TracedMeshes& surfaces,
                    const TracedMeshes& polygons, Ray& ray, Hit& hit);

} // namespace lsys
