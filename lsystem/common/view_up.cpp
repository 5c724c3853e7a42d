#include "lsystem/common/view_up.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace lsys {
namespace {

// Below this sine of the angle between forward and up the right vector is
// taken from the fallback axis: a view within 0.00006° of the vertical.
constexpr float kParallelSine = 1e-6f;

// v over its largest component's magnitude: squares of lengths up to float's
// largest stay finite (a direction 1e20 long would overflow glm::length).
glm::vec3 scaledDown(const glm::vec3& v) {
    const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return largest > 0.0f ? v / largest : v;
}

} // namespace

glm::vec3 viewUp(const glm::vec3& forward, const glm::vec3& up) {
    const glm::vec3 f = scaledDown(forward), u = scaledDown(up);
    const float lengths = glm::length(f) * glm::length(u);
    if (!(lengths > 0.0f) || glm::length(glm::cross(f, u)) > kParallelSine * lengths) return up;
    const glm::vec3 unitUp = glm::normalize(u);
    const glm::vec3 alignment = glm::abs(unitUp);
    const int axis = alignment.x <= alignment.y && alignment.x <= alignment.z ? 0 : alignment.y <= alignment.z ? 1 : 2;
    glm::vec3 right(0.0f);
    right[axis] = 1.0f;
    right = glm::normalize(right - glm::dot(right, unitUp) * unitUp);
    // A look-at basis takes normalize(cross(f, cross(right, f))) = right as its right vector.
    return glm::cross(right, glm::normalize(f));
}

} // namespace lsys
