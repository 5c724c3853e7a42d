#pragma once
// Helpers shared by the turtle tests: parse a native grammar, derive it and
// interpret it; look at segments as start and end points.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "lsystem/language/parser.h"
#include "lsystem/rewriting/plant_from_grammar.h"
#include "lsystem/rewriting/rewriter.h"
#include "lsystem/turtle/turtle.h"

namespace lsys::test {

inline std::string dataPath(const std::string& relative) { return std::string(PLANTFIELD_DATA_DIR) + "/" + relative; }

inline Grammar parseOk(const std::string& source) {
    ParseResult parsed = parseLsystem(source);
    EXPECT_TRUE(parsed.ok()) << formatDiagnostics(parsed.diagnostics, source);
    return std::move(parsed.grammar);
}

// The plant a native grammar draws after its derivation length.
inline PlantAsset plantOf(const std::string& source, const SurfaceLibrary& surfaces = SurfaceLibrary{}) {
    const Grammar grammar = parseOk(source);
    return plantFromGrammar(grammar, derive(grammar), surfaces);
}

inline glm::vec3 headingOf(const Frame& frame) { return frame.rotation * glm::vec3(0.0f, 1.0f, 0.0f); }
inline glm::vec3 leftOf(const Frame& frame) { return frame.rotation * glm::vec3(-1.0f, 0.0f, 0.0f); }

struct Span {
    glm::vec3 start;
    glm::vec3 end;
    float startRadius;
    float endRadius;
    uint32_t material;
    int32_t parent; // the parent joint, which is the index of its segment among the spans
};

// The segments of a plant, in drawing order.
inline std::vector<Span> spansOf(const PlantAsset& plant) {
    std::vector<Span> spans;
    for (const Primitive& p : plant.primitives)
        if (p.kind == PrimitiveKind::Segment)
            spans.push_back({p.frame.position, p.frame.position + headingOf(p.frame) * p.length, p.startRadius,
                             p.endRadius, p.material, plant.joints.at(static_cast<size_t>(p.joint)).parent});
    return spans;
}

inline std::vector<Span> spansOf(const std::string& source) { return spansOf(plantOf(source)); }

inline std::vector<float> stiffnessOf(const PlantAsset& plant) {
    std::vector<float> stiffness;
    for (const Joint& joint : plant.joints) stiffness.push_back(joint.stiffness);
    return stiffness;
}

inline void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(glm::distance(actual, expected), 0.0f, tolerance) << actual.x << "," << actual.y << "," << actual.z;
}

} // namespace lsys::test
