#pragma once
// Helpers shared by the InstanceGraph tests: the graph of a grammar, and the
// comparison of a flattened graph with the turtle's plant.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "../instancing/instancing_test_support.h"
#include "lsystem/instancing/instance_graph.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/turtle/turtle.h"

namespace lsys::test {

inline BGrammar interpretedBGrammar(const Grammar& grammar, std::optional<int> steps = std::nullopt) {
    BGrammarOptions options;
    options.steps = steps;
    options.interpreted = true;
    return buildBGrammar(grammar, options);
}

inline InstanceGraph graphOf(const Grammar& grammar, std::optional<int> steps = std::nullopt,
                             const InstanceGraphOptions& options = {}) {
    return buildInstanceGraph(interpretedBGrammar(grammar, steps), grammar, options);
}

inline PlantAsset turtlePlant(const Grammar& grammar, std::optional<int> steps = std::nullopt) {
    DeriveOptions options;
    options.steps = steps;
    return plantFromGrammar(grammar, derive(grammar, options));
}

// The angle between two rotations, in radians (double: 1e-4 is below what
// acos of a float dot product resolves).
inline double angleBetween(const glm::quat& a, const glm::quat& b) {
    const glm::dquat d = glm::inverse(glm::dquat(a)) * glm::dquat(b);
    return 2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w));
}

inline double plantSize(const PlantAsset& plant) {
    return plant.bounds.empty() ? 1.0
                                : std::max(1.0, static_cast<double>(glm::length(plant.bounds.max - plant.bounds.min)));
}

// The largest distance between the primitives' positions, relative to the plant's size.
inline double largestPositionError(const PlantAsset& actual, const PlantAsset& expected) {
    double error = 0.0;
    const size_t count = std::min(actual.primitives.size(), expected.primitives.size());
    for (size_t i = 0; i < count; ++i)
        error = std::max(error, static_cast<double>(glm::distance(actual.primitives[i].frame.position,
                                                                  expected.primitives[i].frame.position)));
    return error / plantSize(expected);
}

// Frames composed through the graph and turned one by one by the turtle
// drift apart in single precision along chains of tens of thousands of
// turns (ABOP's Koch curves, Fig 1.9e, drift by 5e-4 rad and 2e-4 of their
// size): frames get this many tolerances. A wrong transform is off by far more.
inline constexpr double kFrameDrift = 20.0;

// Radii equal within `tolerance`, relative: a vlab object's pixel-wide lines
// take their width from the plant's extent (widenPixelLines), which the
// flattened frames reproduce within the positions' tolerance.
inline bool sameRadius(float a, float b, double tolerance) {
    return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
}

// Same primitives and joints in the same order: frames within tolerance
// (positions relative to the plant's size, radii relative to themselves),
// everything else equal.
inline void expectSamePlant(const PlantAsset& actual, const PlantAsset& expected, double tolerance = 1e-4) {
    ASSERT_EQ(actual.primitives.size(), expected.primitives.size());
    ASSERT_EQ(actual.joints.size(), expected.joints.size());
    ASSERT_EQ(actual.polygons.size(), expected.polygons.size());
    const double size = plantSize(expected);
    size_t mismatches = 0;
    for (size_t i = 0; i < expected.primitives.size() && mismatches < 10; ++i) {
        const Primitive& a = actual.primitives[i];
        const Primitive& e = expected.primitives[i];
        const bool same = a.kind == e.kind && a.material == e.material && a.joint == e.joint && a.shape == e.shape &&
                          a.length == e.length && sameRadius(a.startRadius, e.startRadius, tolerance) &&
                          sameRadius(a.endRadius, e.endRadius, tolerance) &&
                          glm::distance(a.frame.position, e.frame.position) <= kFrameDrift * tolerance * size &&
                          angleBetween(a.frame.rotation, e.frame.rotation) <= kFrameDrift * tolerance;
        if (!same) ++mismatches;
        EXPECT_TRUE(same) << "primitive " << i << ": position error "
                          << glm::distance(a.frame.position, e.frame.position) / size << ", rotation error "
                          << angleBetween(a.frame.rotation, e.frame.rotation) << ", joint " << a.joint << " vs "
                          << e.joint;
    }
    for (size_t i = 0; i < expected.joints.size(); ++i) {
        EXPECT_EQ(actual.joints[i].parent, expected.joints[i].parent) << "joint " << i;
        EXPECT_EQ(actual.joints[i].stiffness, expected.joints[i].stiffness) << "joint " << i;
        if (actual.joints[i].parent != expected.joints[i].parent) break;
    }
    for (size_t i = 0; i < expected.polygons.size(); ++i) {
        ASSERT_EQ(actual.polygons[i].outline.size(), expected.polygons[i].outline.size()) << "polygon " << i;
        for (size_t v = 0; v < expected.polygons[i].outline.size(); ++v)
            EXPECT_LE(glm::distance(actual.polygons[i].outline[v], expected.polygons[i].outline[v]), tolerance * size);
    }
    ASSERT_EQ(actual.surfaces.size(), expected.surfaces.size());
    for (size_t i = 0; i < expected.surfaces.size(); ++i) EXPECT_EQ(actual.surfaces[i].name, expected.surfaces[i].name);
    ASSERT_EQ(actual.materials.size(), expected.materials.size());
    for (size_t i = 0; i < expected.materials.size(); ++i)
        EXPECT_EQ(actual.materials[i].twoSided, expected.materials[i].twoSided) << "material " << i;
}

} // namespace lsys::test
