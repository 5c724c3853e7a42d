#pragma once
// Exact ray tests against the shapes a plant is drawn with, each in the
// shape's own space (docs/RAYTRACING.md, "Primitive tests"). Every test
// returns the nearest hit with t in [ray.tMin, ray.tMax], so a ray starting
// inside a closed shape hits its wall from within.

#include <optional>

#include <glm/vec3.hpp>

#include "lsystem/plant_asset.h"
#include "lsystem/raytrace/ray.h"

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

// Where the ray enters the box, clamped to tMin (a ray starting inside enters
// at tMin); nothing when the box and [tMin, tMax] do not meet.
std::optional<float> boxEntry(const Ray& ray, const Bounds& box);

} // namespace lsys
