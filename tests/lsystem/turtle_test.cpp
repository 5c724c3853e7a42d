// The 3D turtle: ABOP frame conventions, segments, widths, branching.

#include <cmath>

#include <glm/geometric.hpp>

#include "lsystem/turtle.h"
#include "test_support.h"

namespace lsys::test {
namespace {

std::vector<TurtleSegment> segmentsOf(const std::string& source) {
    Grammar grammar = parseOk(source);
    return turtleSegments(grammar, derive(grammar));
}

void expectNear(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(glm::distance(actual, expected), 0.0f, 1e-5f) << actual.x << "," << actual.y << "," << actual.z;
}

TEST(LsysTurtle, FDrawsAlongTheHeadingWithTheDefaultStep) {
    auto segments = segmentsOf("step: 2\nwidth: 0.5\nAxiom: FF(3)\n");
    ASSERT_EQ(segments.size(), 2u);
    expectNear(segments[0].start, {0, 0, 0});
    expectNear(segments[0].end, {0, 2, 0});
    expectNear(segments[1].end, {0, 5, 0});
    EXPECT_FLOAT_EQ(segments[0].startRadius, 0.25f);
    EXPECT_EQ(segments[0].parent, -1);
    EXPECT_EQ(segments[1].parent, 0);
}

TEST(LsysTurtle, SmallFMovesWithoutDrawing) {
    auto segments = segmentsOf("Axiom: f(2)F\n");
    ASSERT_EQ(segments.size(), 1u);
    expectNear(segments[0].start, {0, 2, 0});
}

TEST(LsysTurtle, PlusTurnsTowardsLeft) {
    // H = +Y, L = -X: '+' turns the heading towards -X (counter-clockwise seen from +Z).
    auto segments = segmentsOf("angle: 90\nAxiom: +F\n");
    expectNear(segments.at(0).end, {-1, 0, 0});
    segments = segmentsOf("angle: 90\nAxiom: -F\n");
    expectNear(segments.at(0).end, {1, 0, 0});
}

TEST(LsysTurtle, PitchAndRoll) {
    // '&' pitches down: the heading turns towards -U (-Z).
    expectNear(segmentsOf("angle: 90\nAxiom: &F\n").at(0).end, {0, 0, -1});
    expectNear(segmentsOf("angle: 90\nAxiom: ^F\n").at(0).end, {0, 0, 1});
    // Rolling does not move the heading, but changes what '+' does afterwards.
    expectNear(segmentsOf("angle: 90\nAxiom: \\(90)F\n").at(0).end, {0, 1, 0});
    expectNear(segmentsOf("angle: 90\nAxiom: /(90)+F\n").at(0).end, {0, 0, -1});
    expectNear(segmentsOf("angle: 90\nAxiom: \\(90)+F\n").at(0).end, {0, 0, 1});
}

TEST(LsysTurtle, TurnAroundAndExplicitAngles) {
    expectNear(segmentsOf("Axiom: |F\n").at(0).end, {0, -1, 0});
    expectNear(segmentsOf("angle: 10\nAxiom: +(90)F\n").at(0).end, {-1, 0, 0});
}

TEST(LsysTurtle, BranchesRestoreStateAndRecordParents) {
    auto segments = segmentsOf("angle: 90\nAxiom: F[+F][-F]F\n");
    ASSERT_EQ(segments.size(), 4u);
    expectNear(segments[1].end, {-1, 1, 0});
    expectNear(segments[2].end, {1, 1, 0});
    expectNear(segments[3].start, {0, 1, 0});
    expectNear(segments[3].end, {0, 2, 0});
    EXPECT_EQ(segments[1].parent, 0);
    EXPECT_EQ(segments[2].parent, 0);
    EXPECT_EQ(segments[3].parent, 0);
}

TEST(LsysTurtle, WidthAndTaper) {
    auto segments = segmentsOf("width: 2\nAxiom: F!(1)F!F(1,0.2)\n");
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_FLOAT_EQ(segments[0].startRadius, 1.0f);
    EXPECT_FLOAT_EQ(segments[1].startRadius, 0.5f);
    EXPECT_FLOAT_EQ(segments[2].startRadius, 0.35f);  // bare ! multiplies by 0.7
    EXPECT_FLOAT_EQ(segments[2].endRadius, 0.1f);
}

std::vector<uint32_t> materialsOf(const std::string& source) {
    std::vector<uint32_t> materials;
    for (const TurtleSegment& segment : segmentsOf(source)) materials.push_back(segment.material);
    return materials;
}

TEST(LsysTurtle, MaterialIndex) { EXPECT_EQ(materialsOf("Axiom: F;(3)F;F'F\n"), (std::vector<uint32_t>{0, 3, 4, 5})); }

TEST(LsysTurtle, RollToHorizontalKeepsHeading) {
    auto segments = segmentsOf("angle: 30\nAxiom: &+/(50)$F+(90)F\n");
    ASSERT_EQ(segments.size(), 2u);
    // After $, L is horizontal, so a yaw keeps the height of the end point.
    glm::vec3 first = segments[0].end - segments[0].start;
    glm::vec3 second = segments[1].end - segments[1].start;
    glm::vec3 left = glm::normalize(second - first * glm::dot(first, second));
    EXPECT_NEAR(left.y, 0.0f, 1e-5f);
}

TEST(LsysTurtle, ScalingModules) {
    auto segments = segmentsOf("angle: 90\nwidth: 1\nAxiom: @Lm(2)F@Am(0.5)+@Wm(0.5)F[@Lm(3)F]F\n");
    ASSERT_EQ(segments.size(), 4u);
    expectNear(segments[0].end, {0, 2, 0});
    const float d = 2.0f * std::sqrt(0.5f);  // length 2 at 45 degrees
    expectNear(segments[1].end, {-d, 2 + d, 0});
    EXPECT_FLOAT_EQ(segments[1].startRadius, 0.25f);
    EXPECT_NEAR(glm::distance(segments[2].start, segments[2].end), 6.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(segments[3].start, segments[3].end), 2.0f, 1e-5f);  // the branch's scale was popped
}

std::vector<float> lengthsOf(const std::string& source) {
    std::vector<float> lengths;
    for (const TurtleSegment& segment : segmentsOf(source)) lengths.push_back(glm::distance(segment.start, segment.end));
    return lengths;
}

void expectNear(const std::vector<float>& actual, const std::vector<float>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 1e-5f) << i;
}

// The branch's change is popped; a bare @La changes nothing.
TEST(LsysTurtle, AddToLength) { expectNear(lengthsOf("step: 2\nAxiom: @La(0.5)F[@La(-1)F]F@La F\n"), {2.5f, 1.5f, 2.5f, 2.5f}); }

TEST(LsysTurtle, SetLength) { expectNear(lengthsOf("step: 2\nAxiom: @Ls(3)F@LsF@Lm(2)F\n"), {3, 3, 6}); }

TEST(LsysTurtle, AddToAngle) {
    auto segments = segmentsOf("angle: 60\nAxiom: @Aa(30)+F\n");
    ASSERT_EQ(segments.size(), 1u);
    expectNear(segments[0].end, {-1, 0, 0});  // 90 degrees towards L = -X
}

TEST(LsysTurtle, SetAngle) {
    auto segments = segmentsOf("angle: 10\nAxiom: @As(180)+F@AsF\n");
    ASSERT_EQ(segments.size(), 2u);
    expectNear(segments[1].end, {0, -2, 0});
}

TEST(LsysTurtle, AddToWidth) {
    auto segments = segmentsOf("width: 1\nAxiom: @Wa(0.5)F@Wa(-1)F\n");
    ASSERT_EQ(segments.size(), 2u);
    EXPECT_FLOAT_EQ(segments[0].startRadius, 0.75f);
    EXPECT_FLOAT_EQ(segments[1].startRadius, 0.25f);
}

// Never below 0.
TEST(LsysTurtle, AddToMaterialIndex) { EXPECT_EQ(materialsOf("Axiom: @Ca(2)F@Ca(-1)F@Ca(-5)F\n"), (std::vector<uint32_t>{2, 1, 0})); }

TEST(LsysTurtle, CutSkipsTheRestOfTheBranch) {
    auto segments = segmentsOf("Axiom: F[F%F[F]F]F\n");
    EXPECT_EQ(segments.size(), 3u);
}

TEST(LsysTurtle, UsesTheInterpretationRules) {
    auto segments = segmentsOf("Axiom: L(2)\ninterpretation:\nL(s) --> F(s)F(s)\n");
    ASSERT_EQ(segments.size(), 2u);
    expectNear(segments[1].end, {0, 4, 0});
}

TEST(LsysTurtle, FrameStaysOrthonormalOverManyTurns) {
    auto segments = segmentsOf("angle: 13.7\nAxiom: A\nA --> +&\\/F^A\nderivation length: 2000\n");
    ASSERT_EQ(segments.size(), 2000u);
    for (const TurtleSegment& segment : segments) ASSERT_NEAR(glm::distance(segment.start, segment.end), 1.0f, 1e-4f);
}

}  // namespace
}  // namespace lsys::test
