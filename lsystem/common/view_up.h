#pragma once
// The up vector a look-at camera is built with, defined for every view
// direction: the field's view matrices (engine/scene/camera.h) and the ray
// tracer's pinhole camera (lsystem/raytrace/render.h) both take it, so a
// camera looking straight down frames the same image in either.

#include <glm/vec3.hpp>

namespace lsys {

// `up` itself when `forward` leans away from it; a look-at basis then takes
// its right vector from cross(forward, up). Along `up` (or against it) that
// cross product vanishes and the basis would be NaN, so the image's right is
// instead the world axis least aligned with `up` (+x for a y-up world; the
// first of x, y, z on a tie), made perpendicular to it: looking straight down
// a y-up world, +x is right and -z (north) is the top of the image. Neither
// vector need be unit length; any finite lengths work.
glm::vec3 viewUp(const glm::vec3& forward, const glm::vec3& up);

} // namespace lsys
