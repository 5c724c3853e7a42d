#include "lsystem/raytrace/traced_primitive.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "lsystem/raytrace/intersect.h"
#include "lsystem/turtle/turtle_builder.h"

namespace lsys {
namespace {

TracedMeshes tracedSurfaces(const std::vector<SurfaceMesh>& surfaces) {
    TracedMeshes traced;
    for (const SurfaceMesh& surface : surfaces) {
        traced.meshes.push_back(surfaceMesh(surface));
        traced.bounds.push_back(boundsOfPoints(surface.positions));
    }
    return traced;
}

Bounds widened(Bounds box) {
    if (box.empty()) return box;
    const glm::vec3 scale = glm::max(glm::abs(box.min), glm::abs(box.max)) + (box.max - box.min);
    const float margin = 1e-5f * std::max({scale.x, scale.y, scale.z});
    box.min -= glm::vec3(margin);
    box.max += glm::vec3(margin);
    return box;
}

std::optional<ShapeHit> nearestTriangle(const Ray& ray, const TriangleMesh& mesh) {
    std::optional<ShapeHit> nearest;
    Ray remaining = ray;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const std::optional<ShapeHit> hit =
            intersectTriangle(remaining, mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                              mesh.positions[mesh.indices[i + 2]]);
        if (hit) {
            nearest = hit;
            remaining.tMax = hit->t;
        }
    }
    return nearest;
}

} // namespace

TracedMeshes tracedPolygons(const std::vector<PolygonShape>& polygons) {
    TracedMeshes traced;
    for (const PolygonShape& polygon : polygons) {
        traced.meshes.push_back(polygonMesh(polygon.outline));
        traced.bounds.push_back(boundsOfPoints(traced.meshes.back().positions));
    }
    return traced;
}

TracedShapes tracedShapesOf(const PlantAsset& plant) {
    return {tracedSurfaces(plant.surfaces), tracedPolygons(plant.polygons)};
}

TracedShapes tracedShapesOf(const InstanceGraph& graph, const SurfaceLibrary& surfaces) {
    std::vector<SurfaceMesh> meshes;
    for (const std::string& name : graph.surfaceNames) meshes.push_back(surfaceOfLook(graph.look, surfaces, name));
    return {tracedSurfaces(meshes), tracedPolygons(graph.polygons)};
}

Primitive tracedPrimitive(const GraphPrimitive& primitive, float lineScale) {
    const float radiusScale = primitive.kind == PrimitiveKind::Segment ? lineScale : 1.0f;
    return {primitive.frame,
            primitive.kind,
            primitive.material,
            -1,
            primitive.shape,
            primitive.length,
            primitive.startRadius * radiusScale,
            primitive.endRadius * radiusScale};
}

Ray rayInFrame(const Ray& ray, const glm::vec3& position, const glm::quat& toLocal) {
    return {toLocal * (ray.origin - position), toLocal * ray.direction, ray.tMin, ray.tMax};
}

Bounds tracedBounds(const Primitive& primitive, const TracedMeshes& surfaces, const TracedMeshes& polygons) {
    if (!isDrawable(primitive)) return {};
    switch (primitive.kind) {
    case PrimitiveKind::Segment: {
        // A frustum is the convex hull of its end discs.
        const glm::vec3 axis = glm::normalize(primitive.frame.rotation * glm::vec3(0.0f, 1.0f, 0.0f));
        Bounds box;
        extendByDisc(box, primitive.frame.position, axis, primitive.startRadius);
        extendByDisc(box, primitive.frame.position + primitive.length * axis, axis, primitive.endRadius);
        return widened(box);
    }
    case PrimitiveKind::Sphere:
        return widened({primitive.frame.position - glm::vec3(primitive.startRadius),
                        primitive.frame.position + glm::vec3(primitive.startRadius)});
    case PrimitiveKind::Surface: {
        const Bounds& local = surfaces.bounds.at(primitive.shape);
        if (local.empty()) return local;
        return widened(transformed({local.min * primitive.length, local.max * primitive.length}, primitive.frame));
    }
    case PrimitiveKind::Polygon: return widened(polygons.bounds.at(primitive.shape));
    }
    return {};
}

bool tracePrimitive(const Primitive& primitive, uint32_t index, const TracedMeshes& surfaces,
                    const TracedMeshes& polygons, Ray& ray, Hit& hit) {
    return tracePrimitive(primitive, glm::inverse(primitive.frame.rotation), index, surfaces, polygons, ray, hit);
}

bool tracePrimitive(const Primitive& primitive, const glm::quat& toLocal, uint32_t index, const TracedMeshes& surfaces,
                    const TracedMeshes& polygons, Ray& ray, Hit& hit) {
    if (!isDrawable(primitive)) return false;
    std::optional<ShapeHit> found;
    if (primitive.kind == PrimitiveKind::Polygon) {
        // The outline is already in the ray's space; the frame is only where it began.
        found = nearestTriangle(ray, polygons.meshes.at(primitive.shape));
    } else {
        // Into the primitive's frame, and for a surface by 1/length into its
        // unit mesh's space (t is unchanged).
        Ray local = rayInFrame(ray, primitive.frame.position, toLocal);
        switch (primitive.kind) {
        case PrimitiveKind::Segment:
            found = intersectFrustum(local, primitive.length, primitive.startRadius, primitive.endRadius);
            break;
        case PrimitiveKind::Sphere: found = intersectSphere(local, primitive.startRadius); break;
        case PrimitiveKind::Surface:
            local.origin /= primitive.length;
            local.direction /= primitive.length;
            found = nearestTriangle(local, surfaces.meshes.at(primitive.shape));
            break;
        case PrimitiveKind::Polygon: break;
        }
        if (found) found->normal = glm::normalize(primitive.frame.rotation * found->normal);
    }
    if (!found) return false;
    hit = {found->t, primitive.kind, primitive.material, index, found->normal};
    ray.tMax = found->t;
    return true;
}

} // namespace lsys
