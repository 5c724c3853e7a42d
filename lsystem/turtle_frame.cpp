#include "lsystem/turtle_frame.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "lsystem/turtle.h"

namespace lsys {

namespace {

// H normalised, L made perpendicular to it, U = H x L: a frame turned in
// several steps stays orthonormal however they round.
void orthonormalise(TurtleState& s) {
    s.heading = glm::normalize(s.heading);
    s.left = glm::normalize(s.left - glm::dot(s.left, s.heading) * s.heading);
    s.up = glm::cross(s.heading, s.left);
}

// ABOP §2.4: after a segment, H turns toward T by e * |H x T| about H x T.
void bendAsAbop(TurtleState& s) {
    const glm::vec3 axis = glm::cross(s.heading, s.tropism);
    const float sine = glm::length(axis);
    if (!(sine > 1e-6f)) return; // parallel to T (or NaN): no defined bend
    rotate(s, axis / sine, glm::degrees(s.elasticity * sine));
}

// Turns heading toward `toward` by the angle whose sine is `sine`, turning
// `toward` with it (cpfg interpret.c, change_dir). A sine past 1 (an
// elasticity above 1) is 1: cpfg's square root of a negative number would
// make the frame NaN.
void turnToward(glm::vec3& heading, glm::vec3& toward, float sine) {
    sine = std::clamp(sine, -1.0f, 1.0f);
    const float cosine = std::sqrt(1.0f - sine * sine);
    const glm::vec3 turned = cosine * heading + sine * toward;
    toward = cosine * toward - sine * heading;
    heading = turned;
}

// cpfg interpret.c, bend: H turns toward U by the angle whose sine is
// e (T . U), then toward L by the angle whose sine is e (T . L). cpfg turns
// toward its own up vector, -U, by the sine e (T . -U): the same turn.
void bendAsCpfg(TurtleState& s) {
    turnToward(s.heading, s.up, s.elasticity * glm::dot(s.tropism, s.up));
    turnToward(s.heading, s.left, s.elasticity * glm::dot(s.tropism, s.left));
    orthonormalise(s);
}

// The up vector for a new heading: the last segment's, turned by the
// rotation that takes the last segment's heading to the new one, so that
// the segments do not twist (cpfg turtle.c, adjust_up_and_left). With the
// two headings parallel cpfg keeps the up vector as it is; here its part
// perpendicular to the heading, so that the frame stays orthonormal (the
// last segment's up when it has none).
glm::vec3 upTurnedWith(const TurtleState& s, glm::vec3 heading) {
    const glm::vec3 axis = glm::cross(s.segmentHeading, heading);
    const float sine = glm::length(axis);
    if (sine > 1e-6f) {
        float angle = std::asin(std::min(sine, 1.0f));
        if (glm::dot(heading, s.segmentHeading) < 0.0f) angle = glm::pi<float>() - angle;
        return glm::angleAxis(angle, axis / sine) * s.segmentUp;
    }
    const glm::vec3 perpendicular = s.up - glm::dot(s.up, heading) * heading;
    return glm::length(perpendicular) > 1e-6f ? glm::normalize(perpendicular) : s.segmentUp;
}

} // namespace

void rotate(TurtleState& s, glm::vec3 axis, float degrees) {
    const glm::quat rotation = glm::angleAxis(glm::radians(degrees), axis);
    s.heading = rotation * s.heading;
    s.left = rotation * s.left;
    orthonormalise(s);
}

void rollHorizontal(TurtleState& s) {
    const glm::vec3 horizontalLeft = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), s.heading);
    if (glm::length(horizontalLeft) < 1e-6f) return; // heading vertical: any roll is horizontal
    s.left = glm::normalize(horizontalLeft);
    s.up = glm::cross(s.heading, s.left);
}

void bendTowardTropism(TurtleState& s, bool cpfg) {
    if (s.elasticity == 0.0f) return;
    if (cpfg)
        bendAsCpfg(s);
    else
        bendAsAbop(s);
}

void setHeadingAsCpfg(TurtleState& s, std::span<const float> p) {
    if (p.size() < 2) return;
    // In double precision, as cpfg's turtle: whether the up vector given is
    // perpendicular to the heading is an exact test.
    glm::dvec3 heading(p[0], p[1], p.size() > 2 ? p[2] : 0.0f);
    const double squared = glm::dot(heading, heading);
    heading = squared == 0.0 ? glm::dvec3(0.0, 1.0, 0.0) : heading * (1.0 / std::sqrt(squared));
    const glm::dvec3 given = p.size() >= 6 ? -glm::dvec3(p[3], p[4], p[5]) : glm::dvec3(0.0); // cpfg's up is -U
    s.heading = glm::vec3(heading);
    if (glm::dot(given, given) != 0.0 && glm::dot(given, heading) == 0.0)
        s.up = glm::vec3(glm::normalize(given));
    else
        s.up = upTurnedWith(s, s.heading);
    s.left = glm::cross(s.up, s.heading);
}

} // namespace lsys
