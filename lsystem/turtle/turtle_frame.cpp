#include "lsystem/turtle/turtle_frame.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "lsystem/turtle/turtle.h"

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
    // |H x T| squares T's size: past about 1.8e19 that overflows to an
    // infinite sine and a NaN frame, so such a T is taken in units of its
    // largest component (smaller ones as they are, their frames unchanged).
    constexpr float kLargestSquarable = 1e18f;
    const float largest = std::max({std::abs(s.tropism.x), std::abs(s.tropism.y), std::abs(s.tropism.z)});
    const float unit = largest > kLargestSquarable ? largest : 1.0f;
    const glm::vec3 axis = glm::cross(s.heading, s.tropism / unit);
    const float sine = glm::length(axis);
    if (!(sine * unit > 1e-6f)) return; // parallel to T (or NaN): no defined bend
    rotate(s, axis / sine, glm::degrees(s.elasticity * sine * unit));
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

// cpfg's rotation of v by the quaternion (cos half, sin half · axis),
// q⁻¹ v q (quaternions.c, rot_by_quat): a turn by -2 half about axis when
// axis is a unit vector. cpfg does not always hand it one (its axis is
// divided by a length clamped to 1); q is then turned as q / |q| turns.
glm::dvec3 rotateAsCpfg(glm::dvec3 v, double half, glm::dvec3 axis) {
    const double sine = std::sin(half);
    const glm::dquat q(std::cos(half), sine * axis.x, sine * axis.y, sine * axis.z);
    const glm::dquat turned = glm::inverse(q) * glm::dquat(0.0, v.x, v.y, v.z) * q;
    return {turned.x, turned.y, turned.z};
}

// The tropisms of movement_adjust and adjust_by_orthotropism (movements.c).
void bendByTropisms(TurtleState& s, std::span<const Movement> movements) {
    const glm::dvec3 heading(s.heading);
    glm::dvec3 toward(0.0);
    for (size_t i = 0; i < movements.size(); ++i) {
        const Movement& movement = movements[i];
        if (movement.kind != MovementKind::Tropism) continue;
        const glm::dvec3 direction(movement.direction);
        const double elasticity = s.movementElasticity[i], gamma = glm::radians(double(movement.angle));
        toward += std::cos(gamma) * elasticity * direction;
        if (std::sin(gamma) == 0.0) continue;
        glm::dvec3 across = glm::cross(heading, direction);
        double length = glm::length(across);
        if (length < 1e-7) across = glm::dvec3(s.left), length = 1.0; // H along T: turn about L
        toward += (elasticity * std::sin(gamma) / length) * glm::cross(direction, across);
    }
    const glm::dvec3 axis = glm::cross(heading, toward);
    double length = glm::length(axis);
    if (length < 1e-6) return;
    length = std::min(length, 1.0);
    s.heading = glm::vec3(rotateAsCpfg(heading, -0.5 * length, axis / length));
    s.up = upTurnedWith(s, s.heading);
    s.left = glm::cross(s.up, s.heading);
}

// The twists of movement_adjust and rotate_to_vector (movements.c), in
// cpfg's up vector, -U. A twist that can act makes this frame the one the
// next @R turns from, as cpfg's does.
void twistByTorques(TurtleState& s, std::span<const Movement> movements) {
    glm::dvec3 twist(0.0);
    for (size_t i = 0; i < movements.size(); ++i)
        if (movements[i].kind == MovementKind::Twist)
            twist += double(s.movementElasticity[i]) * glm::dvec3(movements[i].direction);
    if (twist == glm::dvec3(0.0)) return;
    const glm::dvec3 heading(s.heading);
    const glm::dvec3 across = glm::cross(heading, glm::normalize(twist));
    if (glm::dot(across, across) <= 1e-8) return; // H along the twist: no turn defined
    const glm::dvec3 desired = glm::cross(across, heading) * glm::length(twist);
    const glm::dvec3 up = -glm::dvec3(s.up);
    const glm::dvec3 axis = glm::cross(up, desired);
    double length = glm::length(axis);
    if (length >= 1e-7) {
        length = std::min(length, 1.0);
        s.up = -glm::vec3(rotateAsCpfg(up, 0.5 * length, axis / length));
        s.left = glm::cross(s.up, s.heading);
    }
    s.segmentHeading = s.heading;
    s.segmentUp = s.up;
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

void adjustForMovements(TurtleState& s, std::span<const Movement> movements) {
    if (movements.empty()) return;
    bendByTropisms(s, movements);
    twistByTorques(s, movements);
}

void changeMovementElasticity(TurtleState& s, std::span<const Movement> movements, ElasticityChange change,
                              std::span<const float> p) {
    if (p.empty()) return;
    // cpfg's index is (short)(k - 1), truncated toward 0.
    const double index = double(p[0]) - 1.0;
    if (!(index > -1.0 && index < double(movements.size()))) return;
    const size_t i = static_cast<size_t>(index < 0.0 ? 0.0 : index);
    float& elasticity = s.movementElasticity[i];
    switch (change) {
    case ElasticityChange::Increase: elasticity += p.size() >= 2 ? p[1] : movements[i].increment; break;
    case ElasticityChange::Decrease: elasticity -= p.size() >= 2 ? p[1] : movements[i].increment; break;
    case ElasticityChange::Set: elasticity = p.size() >= 2 ? p[1] : 0.0f; break;
    }
}

} // namespace lsys
