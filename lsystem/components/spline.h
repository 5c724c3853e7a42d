#pragma once
// Tankard 2001, §4.1.1: splines of cubic Hermite patches through control
// points, read at a fractional distance u ∈ [0, 1] along the control points.
// They shape stems and leaves and make spline-valued attributes.

#include <vector>

#include <glm/vec3.hpp>

namespace lsys::components {

// A control point: the curve passes through `position` in the direction of
// `tangent`, whose length is how far the curve keeps to that direction
// (Tankard's orientation angle and magnitude as one vector).
struct SplinePoint {
    glm::vec3 position{0.0f};
    glm::vec3 tangent{0.0f};
};

struct Spline {
    std::vector<SplinePoint> points; // at least one
};

// The tangents a curve gets when its file gives only positions: Catmull–Rom,
// half the chord between each point's neighbours (one-sided at the ends).
void setCatmullRomTangents(std::vector<SplinePoint>& points);

// The patch a fractional distance falls in and the distance within it. The
// thesis's formulas are garbled (its n = ⌈u / (1/(c−1))⌉, l = u / (1−n));
// this is what they mean: n = ⌊u(c−1)⌋, l = u(c−1) − n, with u = 1 read as
// the end of the last patch (n = c−2, l = 1) rather than past it.
struct PatchPosition {
    size_t patch = 0; // between points[patch] and points[patch + 1]
    float local = 0.0f;
};
PatchPosition patchAt(size_t controlPoints, float u);

// The point and the tangent (derivative in u) at fractional distance u,
// clamped to [0, 1]; Tankard approximates the tangent by a second point a
// little further on, we differentiate the patch.
glm::vec3 splinePosition(const Spline& spline, float u);
glm::vec3 splineTangent(const Spline& spline, float u);

// An attribute given as a number or as a spline over the stem's length
// (Tankard §3.2.3.2): a spline-valued one is read from the x coordinate of its
// curve, as Tankard reads a stem's radius and a tree's branch scale.
struct Attribute {
    float value = 0.0f;
    Spline spline; // empty: single-valued
};
Attribute constant(float value);
float valueAt(const Attribute& attribute, float u);

} // namespace lsys::components
