#pragma once
// Helpers shared by the ramification tests: plants from L-system text or data files.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "lsystem/language/parser.h"
#include "lsystem/ramification/ramification.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/surfaces.h"
#include "lsystem/turtle/turtle.h"
#include "lsystem/vlab/object.h"

namespace lsys::test {

inline std::string dataPath(const std::string& relative) { return std::string(PLANTFIELD_DATA_DIR) + "/" + relative; }
inline std::string testDataPath(const std::string& name) { return std::string(RAMIFICATION_TEST_DATA) + "/" + name; }

// The plant a file (an L-system or a vlab object) draws after its derivation length.
inline PlantAsset plantOfFile(const std::string& path) {
    vlab::PlantFile plant = vlab::loadPlant(path);
    EXPECT_TRUE(plant.parsed.ok()) << formatDiagnostics(plant.parsed.diagnostics, plant.source);
    const Grammar& grammar = plant.parsed.grammar;
    return plantFromGrammar(grammar, derive(grammar), SurfaceLibrary(meshDirectoriesFor(path)));
}

// The plant the axiom `word` draws.
inline PlantAsset plantOfWord(const std::string& word) {
    const std::string source = "derivation length: 0\nAxiom: " + word + "\n";
    ParseResult parsed = parseLsystem(source);
    EXPECT_TRUE(parsed.ok()) << formatDiagnostics(parsed.diagnostics, source);
    return plantFromGrammar(parsed.grammar, derive(parsed.grammar));
}

inline glm::vec3 headingOf(const Joint& joint) { return joint.rest.rotation * glm::vec3(0, 1, 0); }

inline double degreesBetween(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

// A child of a branch point: its order, its sibling's, its parent's, and the
// angle between its heading and its parent's.
struct ChildAngle {
    size_t joint = 0;
    uint32_t parentOrder = 0, own = 0, sibling = 0;
    double degrees = 0.0;
};

// Every child of every branch point of a generated tree (binary: a branch
// point of another number of children is a failure).
inline std::vector<ChildAngle> childAngles(const PlantAsset& plant, const CompiledRamification& compiled) {
    std::vector<std::vector<size_t>> children(plant.joints.size());
    for (size_t i = 0; i < plant.joints.size(); ++i)
        if (plant.joints[i].parent >= 0) children[plant.joints[i].parent].push_back(i);
    std::vector<ChildAngle> angles;
    for (size_t i = 0; i < plant.joints.size(); ++i) {
        if (children[i].empty()) continue;
        EXPECT_EQ(children[i].size(), 2u) << "joint " << i;
        if (children[i].size() != 2) continue;
        for (size_t child : children[i])
            angles.push_back({child, compiled.jointOrder[i], compiled.jointOrder[child],
                              compiled.jointOrder[children[i][0] + children[i][1] - child],
                              degreesBetween(headingOf(plant.joints[i]), headingOf(plant.joints[child]))});
    }
    return angles;
}

} // namespace lsys::test
