#pragma once
// Exact ray tests against the shapes a plant is drawn with, each in the
// shape's own space (docs/RAYTRACING.md, "Primitive tests"). Every test
// returns the nearest hit with t in [ray.tMin, ray.tMax], so a ray starting
// inside a closed shape hits its wall from within.

#include <algorithm>
#include <optional>
#include <utility>

#include <glm/vec3.hpp>

#include "lsystem/raytrace/ray.h"
#include "lsystem/turtle/plant_asset.h"

namespace lsys {

struct ShapeHit {
    float t = 0.0f;
    glm::vec3 normal{0.0f}; // unit, as Hit::normal
};

// The closed cone frustum along +Y from radius startRadius at y = 0 to
// endRadius at y = length: its side and both end discs (the caps segmentMesh
// closes a segment with by default). A zero radius has no disc.
std::optional<ShapeHit> intersectFrustum(const Ray& ray, float length, float startRadius, float endRadius);

// The sphere of `radius` about the origin.
std::optional<ShapeHit> intersectSphere(const Ray& ray, float radius);

// The triangle a, b, c from either side (Möller and Trumbore 1997); the
// normal is that of (b − a) × (c − a).
std::optional<ShapeHit> intersectTriangle(const Ray& ray, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// A ray as the box test takes it: the reciprocal of its direction computed
// once for the many boxes a BVH walk tests (±infinity along an axis the ray
// is parallel to).
struct BoxRay {
    glm::vec3 origin;
    glm::vec3 inverseDirection;
    float tMin;
};

inline BoxRay boxRayOf(const Ray& ray) { return {ray.origin, 1.0f / ray.direction, ray.tMin}; }

// Where the ray enters the non-empty box, clamped to tMin (a ray starting
// inside enters at tMin); nothing when the box and [tMin, tMax] do not meet.
// The slabs of Kay and Kajiya (1986). A ray parallel to an axis with its
// origin on a face of the box makes 0 · ∞, NaN, which std::max and std::min
// ignore as their second argument: the ray is inside that slab.
inline std::optional<float> boxEntry(const BoxRay& ray, const Bounds& box, float tMax) {
    float enter = ray.tMin, leave = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        float near = (box.min[axis] - ray.origin[axis]) * ray.inverseDirection[axis];
        float far = (box.max[axis] - ray.origin[axis]) * ray.inverseDirection[axis];
        if (near > far) std::swap(near, far);
        enter = std::max(enter, near);
        leave = std::min(leave, far);
    }
    if (!(enter <= leave)) return std::nullopt;
    return enter;
}

// The same for one ray and any box (nothing for an empty one).
inline std::optional<float> boxEntry(const Ray& ray, const Bounds& box) {
    if (box.empty()) return std::nullopt;
    return boxEntry(boxRayOf(ray), box, ray.tMax);
}

} // namespace lsys
