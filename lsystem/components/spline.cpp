#include "lsystem/components/spline.h"

#include <algorithm>
#include <cmath>

namespace lsys::components {

void setCatmullRomTangents(std::vector<SplinePoint>& points) {
    const size_t c = points.size();
    if (c < 2) return;
    for (size_t i = 0; i < c; ++i) {
        const size_t before = i == 0 ? 0 : i - 1;
        const size_t after = i + 1 == c ? c - 1 : i + 1;
        const float span = float(after - before); // 2 inside, 1 at the ends
        points[i].tangent = (points[after].position - points[before].position) / span;
    }
}

PatchPosition patchAt(size_t controlPoints, float u) {
    if (controlPoints < 2) return {0, 0.0f};
    const float patches = float(controlPoints - 1);
    const float scaled = std::clamp(u, 0.0f, 1.0f) * patches;
    const size_t patch = std::min(size_t(std::floor(scaled)), controlPoints - 2);
    return {patch, scaled - float(patch)};
}

namespace {

// The Hermite basis at l and its derivative.
struct HermiteWeights {
    float p0, m0, p1, m1;
};

HermiteWeights hermiteBasis(float l) {
    const float l2 = l * l, l3 = l2 * l;
    return {2 * l3 - 3 * l2 + 1, l3 - 2 * l2 + l, -2 * l3 + 3 * l2, l3 - l2};
}

HermiteWeights hermiteDerivative(float l) {
    const float l2 = l * l;
    return {6 * l2 - 6 * l, 3 * l2 - 4 * l + 1, -6 * l2 + 6 * l, 3 * l2 - 2 * l};
}

glm::vec3 hermiteAt(const Spline& spline, float u, HermiteWeights (*basis)(float), glm::vec3 single) {
    if (spline.points.size() < 2) return single;
    const PatchPosition at = patchAt(spline.points.size(), u);
    const SplinePoint& a = spline.points[at.patch];
    const SplinePoint& b = spline.points[at.patch + 1];
    const HermiteWeights w = basis(at.local);
    return w.p0 * a.position + w.m0 * a.tangent + w.p1 * b.position + w.m1 * b.tangent;
}

} // namespace

glm::vec3 splinePosition(const Spline& spline, float u) {
    return hermiteAt(spline, u, hermiteBasis, spline.points.empty() ? glm::vec3(0.0f) : spline.points[0].position);
}

glm::vec3 splineTangent(const Spline& spline, float u) {
    return hermiteAt(spline, u, hermiteDerivative, spline.points.empty() ? glm::vec3(0.0f) : spline.points[0].tangent);
}

Attribute constant(float value) { return {value, {}}; }

float valueAt(const Attribute& attribute, float u) {
    return attribute.spline.points.empty() ? attribute.value : splinePosition(attribute.spline, u).x;
}

} // namespace lsys::components
