#include "lsystem/raytrace/intersect.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

namespace lsys {
namespace {

// The shape tests work in double: a float quadratic loses the hit of a
// grazing ray on a thin twig seen from across the plant.
struct Nearest {
    double tMin, tMax;
    double t = 0.0;
    glm::dvec3 normal{0.0};
    bool found = false;

    void offer(double candidate, const glm::dvec3& n) {
        // Written so that a NaN (a ray of infinite or NaN coordinates) is never a hit.
        if (!(candidate >= tMin && candidate <= tMax) || (found && candidate >= t)) return;
        t = candidate;
        normal = n;
        found = true;
    }
    std::optional<ShapeHit> result() const {
        if (!found) return std::nullopt;
        const double length = glm::length(normal);
        return ShapeHit{float(t), glm::vec3(length > 0.0 ? normal / length : glm::dvec3(0.0, 1.0, 0.0))};
    }
};

// The roots of a·t² + b·t + c in the form that does not cancel (Press et al.,
// Numerical Recipes §5.6); a = 0 leaves the linear root.
template <typename Offer>
void quadraticRoots(double a, double b, double c, Offer&& offer) {
    if (a == 0.0) {
        if (b != 0.0) offer(-c / b);
        return;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    offer(q / a);
    if (q != 0.0) offer(c / q);
}

} // namespace

std::optional<ShapeHit> intersectFrustum(const Ray& ray, float length, float startRadius, float endRadius) {
    if (!(length > 0.0f)) return std::nullopt;
    const glm::dvec3 o(ray.origin), d(ray.direction);
    const double l = length, r0 = startRadius, r1 = endRadius;
    const double slope = (r1 - r0) / l; // radius gained per unit of height
    Nearest nearest{ray.tMin, ray.tMax};

    // The side: x² + z² = r(y)², r(y) = r0 + slope·y, for 0 ≤ y ≤ length.
    const double radiusAtOrigin = r0 + slope * o.y;
    const double a = d.x * d.x + d.z * d.z - slope * slope * d.y * d.y;
    const double b = 2.0 * (o.x * d.x + o.z * d.z - slope * d.y * radiusAtOrigin);
    const double c = o.x * o.x + o.z * o.z - radiusAtOrigin * radiusAtOrigin;
    quadraticRoots(a, b, c, [&](double t) {
        const glm::dvec3 p = o + t * d;
        const double radius = r0 + slope * p.y;
        if (p.y < 0.0 || p.y > l || radius < 0.0) return;
        // The gradient of x² + z² − r(y)², pointing out of the cone.
        nearest.offer(t, glm::dvec3(p.x, -slope * radius, p.z));
    });
    // The end discs.
    if (d.y != 0.0) {
        const std::pair<double, double> caps[] = {{0.0, r0}, {l, r1}};
        for (const auto& [height, radius] : caps) {
            const double t = (height - o.y) / d.y;
            const glm::dvec3 p = o + t * d;
            if (radius > 0.0 && p.x * p.x + p.z * p.z <= radius * radius)
                nearest.offer(t, glm::dvec3(0.0, height == 0.0 ? -1.0 : 1.0, 0.0));
        }
    }
    return nearest.result();
}

std::optional<ShapeHit> intersectSphere(const Ray& ray, float radius) {
    const glm::dvec3 o(ray.origin), d(ray.direction);
    const double r = radius;
    Nearest nearest{ray.tMin, ray.tMax};
    quadraticRoots(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - r * r,
                   [&](double t) { nearest.offer(t, o + t * d); });
    return nearest.result();
}

std::optional<ShapeHit> intersectTriangle(const Ray& ray, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 o(ray.origin), d(ray.direction), va(a);
    const glm::dvec3 edge1 = glm::dvec3(b) - va, edge2 = glm::dvec3(c) - va;
    const glm::dvec3 p = glm::cross(d, edge2);
    const double determinant = glm::dot(edge1, p);
    if (determinant == 0.0) return std::nullopt; // parallel to the plane, or a degenerate triangle
    const double inverse = 1.0 / determinant;
    const glm::dvec3 s = o - va;
    const double u = glm::dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, edge1);
    const double v = glm::dot(d, q) * inverse;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    Nearest nearest{ray.tMin, ray.tMax};
    nearest.offer(glm::dot(edge2, q) * inverse, glm::cross(edge1, edge2));
    return nearest.result();
}

} // namespace lsys
