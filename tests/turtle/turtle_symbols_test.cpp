// The 3D turtle, symbol by symbol: ABOP frame conventions, segments, widths,
// branching, materials, the @ modules, spheres, surfaces and polygons.

#include <cmath>

#include "turtle_test_support.h"

namespace lsys::test {
namespace {

TEST(LsysTurtle, FDrawsAlongTheHeadingWithTheDefaultStep) {
    auto segments = spansOf("step: 2\nwidth: 0.5\nAxiom: FF(3)\n");
    ASSERT_EQ(segments.size(), 2u);
    expectNear(segments[0].start, {0, 0, 0});
    expectNear(segments[0].end, {0, 2, 0});
    expectNear(segments[1].end, {0, 5, 0});
    EXPECT_FLOAT_EQ(segments[0].startRadius, 0.25f);
    EXPECT_EQ(segments[0].parent, -1);
    EXPECT_EQ(segments[1].parent, 0);
}

TEST(LsysTurtle, SmallFMovesWithoutDrawing) {
    auto segments = spansOf("Axiom: f(2)F\n");
    ASSERT_EQ(segments.size(), 1u);
    expectNear(segments[0].start, {0, 2, 0});
}

TEST(LsysTurtle, PlusTurnsTowardsLeft) {
    // H = +Y, L = -X: '+' turns the heading towards -X (counter-clockwise seen from +Z).
    auto segments = spansOf("angle: 90\nAxiom: +F\n");
    expectNear(segments.at(0).end, {-1, 0, 0});
    segments = spansOf("angle: 90\nAxiom: -F\n");
    expectNear(segments.at(0).end, {1, 0, 0});
}

TEST(LsysTurtle, PitchAndRoll) {
    // '&' pitches down: the heading turns towards -U (-Z).
    expectNear(spansOf("angle: 90\nAxiom: &F\n").at(0).end, {0, 0, -1});
    expectNear(spansOf("angle: 90\nAxiom: ^F\n").at(0).end, {0, 0, 1});
    // Rolling does not move the heading, but changes what '+' does afterwards.
    expectNear(spansOf("angle: 90\nAxiom: \\(90)F\n").at(0).end, {0, 1, 0});
    expectNear(spansOf("angle: 90\nAxiom: /(90)+F\n").at(0).end, {0, 0, -1});
    expectNear(spansOf("angle: 90\nAxiom: \\(90)+F\n").at(0).end, {0, 0, 1});
}

TEST(LsysTurtle, TurnAroundAndExplicitAngles) {
    expectNear(spansOf("Axiom: |F\n").at(0).end, {0, -1, 0});
    expectNear(spansOf("angle: 10\nAxiom: +(90)F\n").at(0).end, {-1, 0, 0});
}

TEST(LsysTurtle, BranchesRestoreStateAndRecordParents) {
    auto segments = spansOf("angle: 90\nAxiom: F[+F][-F]F\n");
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
    auto segments = spansOf("width: 2\nAxiom: F!(1)F!F(1,0.2)\n");
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_FLOAT_EQ(segments[0].startRadius, 1.0f);
    EXPECT_FLOAT_EQ(segments[1].startRadius, 0.5f);
    EXPECT_FLOAT_EQ(segments[2].startRadius, 0.35f); // bare ! multiplies by 0.7
    EXPECT_FLOAT_EQ(segments[2].endRadius, 0.1f);
}

std::vector<uint32_t> materialsOf(const std::string& source) {
    std::vector<uint32_t> materials;
    for (const Span& segment : spansOf(source)) materials.push_back(segment.material);
    return materials;
}

TEST(LsysTurtle, MaterialIndex) { EXPECT_EQ(materialsOf("Axiom: F;(3)F;F'F\n"), (std::vector<uint32_t>{0, 3, 4, 5})); }

// cpfg's '#' and ',' are the counterparts of '!' and ';'.
TEST(LsysTurtle, HashWidensAndCommaLowersTheMaterial) {
    auto segments = spansOf("width: 2\nAxiom: F#(1)F!#F\n");
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_FLOAT_EQ(segments[1].startRadius, 0.5f);
    EXPECT_FLOAT_EQ(segments[2].startRadius, 0.5f); // a bare # undoes a bare !
    EXPECT_EQ(materialsOf("Axiom: ;(5)F,F,(2)F,F,F\n"), (std::vector<uint32_t>{5, 4, 2, 1, 0}));
}

TEST(LsysTurtle, RollToHorizontalKeepsHeading) {
    auto segments = spansOf("angle: 30\nAxiom: &+/(50)$F+(90)F\n");
    ASSERT_EQ(segments.size(), 2u);
    // After $, L is horizontal, so a yaw keeps the height of the end point.
    glm::vec3 first = segments[0].end - segments[0].start;
    glm::vec3 second = segments[1].end - segments[1].start;
    glm::vec3 left = glm::normalize(second - first * glm::dot(first, second));
    EXPECT_NEAR(left.y, 0.0f, 1e-5f);
    // cpfg's @v is the same roll.
    auto cpfg = spansOf("angle: 30\nAxiom: &+/(50)@vF+(90)F\n");
    ASSERT_EQ(cpfg.size(), 2u);
    expectNear(cpfg[1].end, segments[1].end);
}

TEST(LsysTurtle, ScalingModules) {
    auto segments = spansOf("angle: 90\nwidth: 1\nAxiom: @Lm(2)F@Am(0.5)+@Wm(0.5)F[@Lm(3)F]F\n");
    ASSERT_EQ(segments.size(), 4u);
    expectNear(segments[0].end, {0, 2, 0});
    const float d = 2.0f * std::sqrt(0.5f); // length 2 at 45 degrees
    expectNear(segments[1].end, {-d, 2 + d, 0});
    EXPECT_FLOAT_EQ(segments[1].startRadius, 0.25f);
    EXPECT_NEAR(glm::distance(segments[2].start, segments[2].end), 6.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(segments[3].start, segments[3].end), 2.0f, 1e-5f); // the branch's scale was popped
}

std::vector<float> lengthsOf(const std::string& source) {
    std::vector<float> lengths;
    for (const Span& segment : spansOf(source)) lengths.push_back(glm::distance(segment.start, segment.end));
    return lengths;
}

void expectLengthsNear(const std::vector<float>& actual, const std::vector<float>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 1e-5f) << i;
}

// The branch's change is popped; a bare @La changes nothing.
TEST(LsysTurtle, AddToLength) {
    expectLengthsNear(lengthsOf("step: 2\nAxiom: @La(0.5)F[@La(-1)F]F@La F\n"), {2.5f, 1.5f, 2.5f, 2.5f});
}

TEST(LsysTurtle, SetLength) { expectLengthsNear(lengthsOf("step: 2\nAxiom: @Ls(3)F@LsF@Lm(2)F\n"), {3, 3, 6}); }

TEST(LsysTurtle, AddToAngle) {
    auto segments = spansOf("angle: 60\nAxiom: @Aa(30)+F\n");
    ASSERT_EQ(segments.size(), 1u);
    expectNear(segments[0].end, {-1, 0, 0}); // 90 degrees towards L = -X
}

TEST(LsysTurtle, SetAngle) {
    auto segments = spansOf("angle: 10\nAxiom: @As(180)+F@AsF\n");
    ASSERT_EQ(segments.size(), 2u);
    expectNear(segments[1].end, {0, -2, 0});
}

TEST(LsysTurtle, AddToWidth) {
    auto segments = spansOf("width: 1\nAxiom: @Wa(0.5)F@Wa(-1)F\n");
    ASSERT_EQ(segments.size(), 2u);
    EXPECT_FLOAT_EQ(segments[0].startRadius, 0.75f);
    EXPECT_FLOAT_EQ(segments[1].startRadius, 0.25f);
}

// Never below 0.
TEST(LsysTurtle, AddToMaterialIndex) {
    EXPECT_EQ(materialsOf("Axiom: @Ca(2)F@Ca(-1)F@Ca(-5)F\n"), (std::vector<uint32_t>{2, 1, 252})); // modulo 256
}

TEST(LsysTurtle, CutSkipsTheRestOfTheBranch) {
    auto segments = spansOf("Axiom: F[F%F[F]F]F\n");
    EXPECT_EQ(segments.size(), 3u);
}

TEST(LsysTurtle, UsesTheInterpretationRules) {
    auto segments = spansOf("Axiom: L(2)\ninterpretation:\nL(s) --> F(s)F(s)\n");
    ASSERT_EQ(segments.size(), 2u);
    expectNear(segments[1].end, {0, 4, 0});
}

TEST(LsysTurtle, FrameStaysOrthonormalOverManyTurns) {
    auto segments = spansOf("angle: 13.7\nAxiom: A\nA --> +&\\/F^A\nderivation length: 2000\n");
    ASSERT_EQ(segments.size(), 2000u);
    for (const Span& segment : segments) ASSERT_NEAR(glm::distance(segment.start, segment.end), 1.0f, 1e-4f);
}

// cpfg's colour index wraps around its 256-entry map (interpret.c, ';' and ','):
// 255 + 1 is 0, 300 is 44, -2 is 254, and a bare , below 0 is 255.
TEST(LsysTurtle, MaterialIndicesWrapAroundTheColorMap) {
    EXPECT_EQ(materialsOf("Axiom: ;(255)F;F;(300)F;(-2)F;(0),F;(2.9)F\n"),
              (std::vector<uint32_t>{255, 0, 44, 254, 255, 2}));
}

// A grammar's TurtleStyle (set from a vlab object's view file) steps the
// bare width and colour modules by cpfg's increments instead of ABOP's factor.
TEST(LsysTurtle, StyleIncrementsStepBareWidthAndColor) {
    ParseResult parsed = parseLsystem("width: 5\nAxiom: F!F!F#F;F;F,F\n");
    ASSERT_TRUE(parsed.ok());
    parsed.grammar.style.widthFactor = 1.0;
    parsed.grammar.style.widthIncrement = 2.0;
    parsed.grammar.style.colorIncrement = 3;
    parsed.grammar.style.material = 254;
    const std::vector<Span> spans = spansOf(plantFromGrammar(parsed.grammar, derive(parsed.grammar)));
    ASSERT_EQ(spans.size(), 7u);
    const float radii[] = {2.5f, 1.5f, 0.5f, 1.5f, 1.5f, 1.5f, 1.5f};
    const uint32_t materials[] = {254, 254, 254, 254, 1, 4, 1};
    for (size_t i = 0; i < spans.size(); ++i) {
        EXPECT_FLOAT_EQ(spans[i].startRadius, radii[i]) << i;
        EXPECT_EQ(spans[i].material, materials[i]) << i;
    }
    // A bare ! never makes a width negative.
    ParseResult thin = parseLsystem("width: 1\nAxiom: !F\n");
    thin.grammar.style = parsed.grammar.style;
    EXPECT_FLOAT_EQ(spansOf(plantFromGrammar(thin.grammar, derive(thin.grammar))).at(0).startRadius, 0.0f);
}

// cpfg's G and g (read from cpfg files only): G draws as F and g moves as f,
// but inside a polygon neither records a vertex.
TEST(LsysTurtle, CpfgsGAndgRecordNoPolygonVertex) {
    ParseResult parsed = parseLsystem("angle: 90\nAxiom: FGg{.f+G+f.}{.f+g+f.}\n");
    ASSERT_TRUE(parsed.ok());
    PlantAsset plant = plantFromGrammar(parsed.grammar, derive(parsed.grammar));
    EXPECT_EQ(spansOf(plant).size(), 1u); // natively G and g are ordinary modules, and F inside { } moves
    parsed.grammar.style.cpfgModules = true;
    plant = plantFromGrammar(parsed.grammar, derive(parsed.grammar));
    EXPECT_EQ(spansOf(plant).size(), 2u); // F and G
    ASSERT_EQ(plant.polygons.size(), 2u);
    // The corner G or g reaches is no vertex: (0,3) (0,4) [(-1,4)] (-1,3), then (-1,3) (-1,2) [(0,2)] (0,3).
    for (const PolygonShape& polygon : plant.polygons) ASSERT_EQ(polygon.outline.size(), 3u);
    expectNear(plant.polygons[0].outline[2], {-1, 3, 0});
    expectNear(plant.polygons[1].outline[2], {0, 3, 0});
}

// cpfg's @M and @R (blackbox.c, read from cpfg files only): @M moves to a
// point and @R sets the heading, both in plant space; with fewer than two
// parameters neither does anything, and @R(0,0,0) heads along +Y.
TEST(LsysTurtle, CpfgsAtMMovesToAPointAndAtRSetsTheHeading) {
    const char* axiom = "Axiom: F@M(2,3)F@M(1)F@M(0,0,5)@R(1,0,0)F@R(0)F@R(0,0,0)F\n";
    expectNear(spansOf(plantOf(axiom)).back().end, {0, 6, 0}); // natively ordinary modules
    const PlantAsset plant = plantOf(std::string("turtle modules: cpfg\n") + axiom);
    const std::vector<Span> spans = spansOf(plant);
    ASSERT_EQ(spans.size(), 6u);
    expectNear(spans[1].start, {2, 3, 0});
    expectNear(spans[2].start, {2, 4, 0});
    expectNear(spans[3].start, {0, 0, 5});
    expectNear(spans[3].end, {1, 0, 5});
    expectNear(spans[4].end, {2, 0, 5});
    expectNear(spans[5].end, {2, 1, 5});
    // The up vector is the last segment's, turned as the heading turned: +Z about Z.
    expectNear(leftOf(plant.primitives[3].frame), {0, 1, 0});
}

// @R's up vector is cpfg's, L x H (ours is H x L): U is its opposite when it
// is perpendicular to the heading; otherwise U is the last segment's turned
// with the heading (cpfg turtle.c, adjust_up_and_left), not the current one.
TEST(LsysTurtle, CpfgsAtRTakesAnUpVectorOrKeepsTheSegmentsFromTwisting) {
    const float a = std::sqrt(0.5f);
    PlantAsset plant = plantOf("turtle modules: cpfg\nAxiom: @R(0,1,1,1,0,0)F\n");
    ASSERT_EQ(plant.primitives.size(), 1u);
    expectNear(headingOf(plant.primitives[0].frame), {0, a, a});
    expectNear(leftOf(plant.primitives[0].frame), {0, a, -a});
    expectNear(plant.primitives[0].frame.rotation * glm::vec3(0, 0, 1), {-1, 0, 0});
    // After the pitch U is +Y; the up given is not perpendicular to H = +X.
    plant = plantOf("turtle modules: cpfg\nAxiom: F&(90)@R(1,0,0,1,1,0)F\n");
    ASSERT_EQ(plant.primitives.size(), 2u);
    expectNear(headingOf(plant.primitives[1].frame), {1, 0, 0});
    expectNear(leftOf(plant.primitives[1].frame), {0, 1, 0});
}

// Pixel widths (a view file's "initial line width: 2 pixels") become a
// fraction of the plant's extent: 320 pixels across its larger side.
TEST(LsysTurtle, PixelLinesAreAFractionOfThePlant) {
    ParseResult parsed = parseLsystem("width: 4\nAxiom: F(32)+(90)F(16)\n");
    ASSERT_TRUE(parsed.ok());
    parsed.grammar.style.pixelLines = true;
    const PlantAsset plant = plantFromGrammar(parsed.grammar, derive(parsed.grammar));
    // Interpreted in pixels the plant spans 18 in x and 34 in y (the second
    // segment's end disc, 2 pixels in radius, reaches y = 34): a pixel is 34/320.
    ASSERT_EQ(plant.joints.size(), 2u);
    EXPECT_FLOAT_EQ(plant.joints[0].startRadius, 2.0f * 34.0f / 320.0f);
    EXPECT_FLOAT_EQ(plant.primitives[1].endRadius, 2.0f * 34.0f / 320.0f);
}

TEST(LsysTurtle, UnmatchedPopIsIgnored) {
    auto segments = spansOf("Axiom: F]F\n");
    ASSERT_EQ(segments.size(), 2u);
    expectNear(segments[1].end, {0, 2, 0});
}

TEST(LsysTurtle, NegativeLengthDrawsBackwards) {
    const PlantAsset plant = plantOf("Axiom: F(-2)F\n");
    ASSERT_EQ(plant.primitives.size(), 2u);
    EXPECT_FLOAT_EQ(plant.primitives[0].length, 2.0f);
    expectNear(headingOf(plant.primitives[0].frame), {0, -1, 0});
    expectNear(spansOf(plant)[1].start, {0, -2, 0});
}

TEST(LsysTurtle, StiffnessModuleSetsTheFollowingJoints) {
    // The branch's stiffness is popped; a bare @K changes nothing.
    EXPECT_EQ(stiffnessOf(plantOf("Axiom: F@K(3)F[@K(7)F]F@KF\n")), (std::vector<float>{0, 3, 7, 3, 3}));
}

TEST(LsysTurtle, SphereOfAGivenDiameterOrTheWidth) {
    const PlantAsset plant = plantOf("width: 0.4\nAxiom: @O(2)F@O\n");
    ASSERT_EQ(plant.primitives.size(), 3u);
    const Primitive& big = plant.primitives[0];
    const Primitive& small = plant.primitives[2];
    EXPECT_EQ(big.kind, PrimitiveKind::Sphere);
    EXPECT_FLOAT_EQ(big.startRadius, 1.0f);
    EXPECT_EQ(big.joint, -1);
    EXPECT_EQ(small.kind, PrimitiveKind::Sphere);
    EXPECT_FLOAT_EQ(small.startRadius, 0.2f);
    EXPECT_EQ(small.joint, 0);
    expectNear(small.frame.position, {0, 1, 0});
}

TEST(LsysTurtle, CircleIsIgnored) { EXPECT_TRUE(plantOf("Axiom: @Oc(2)@Oc\n").primitives.empty()); }

TEST(LsysTurtle, SurfacesAreScaledAndShared) {
    const PlantAsset plant = plantOf("Axiom: F~leaf(2)~petal~leaf\n");
    ASSERT_EQ(plant.primitives.size(), 4u);
    ASSERT_EQ(plant.surfaces.size(), 2u); // the second ~leaf reuses the first's mesh
    EXPECT_EQ(plant.surfaces[0].name, "leaf");
    EXPECT_EQ(plant.surfaces[1].name, "petal");
    const Primitive& leaf = plant.primitives[1];
    EXPECT_EQ(leaf.kind, PrimitiveKind::Surface);
    EXPECT_EQ(leaf.shape, 0u);
    EXPECT_FLOAT_EQ(leaf.length, 2.0f);
    expectNear(leaf.frame.position, {0, 1, 0});
    EXPECT_EQ(plant.primitives[2].shape, 1u);
    EXPECT_FLOAT_EQ(plant.primitives[2].length, 1.0f); // bare: scale 1
    EXPECT_EQ(plant.primitives[3].shape, 0u);
}

TEST(LsysTurtle, PolygonFromExplicitVertices) {
    // ABOP: { starts a polygon, . records a vertex. f records one too (lpfg),
    // so ABOP's ".f." gives each corner once.
    const PlantAsset plant = plantOf("angle: 90\nAxiom: {.f.+f.+f.}\n");
    ASSERT_EQ(plant.polygons.size(), 1u);
    const std::vector<glm::vec3>& outline = plant.polygons[0].outline;
    ASSERT_EQ(outline.size(), 4u);
    expectNear(outline[0], {0, 0, 0});
    expectNear(outline[1], {0, 1, 0});
    expectNear(outline[2], {-1, 1, 0});
    expectNear(outline[3], {-1, 0, 0});
    ASSERT_EQ(plant.primitives.size(), 1u);
    EXPECT_EQ(plant.primitives[0].kind, PrimitiveKind::Polygon);
    EXPECT_EQ(plant.primitives[0].shape, 0u);
}

TEST(LsysTurtle, PolygonTracedWithFDrawsNoSegments) {
    // Robbins' leaf: F inside { } records the vertex it reaches and draws nothing.
    const PlantAsset plant = plantOf("Axiom: {+(30)F-(120)F-(120)F}F\n");
    ASSERT_EQ(plant.polygons.size(), 1u);
    EXPECT_EQ(plant.polygons[0].outline.size(), 3u); // the third F returns to the start
    EXPECT_EQ(spansOf(plant).size(), 1u);            // only the F after }
    expectNear(plant.polygons[0].outline[2], {0, 0, 0});
}

TEST(LsysTurtle, PolygonOutlivesTheBranchItWasOpenedIn) {
    // ABOP Fig 5.6's [+A{.].C.}: the polygon stack is not the branch stack.
    const PlantAsset plant = plantOf("angle: 90\nAxiom: [+{.f.]f.}\n");
    ASSERT_EQ(plant.polygons.size(), 1u);
    const std::vector<glm::vec3>& outline = plant.polygons[0].outline;
    ASSERT_EQ(outline.size(), 3u);
    expectNear(outline[1], {-1, 0, 0});
    expectNear(outline[2], {0, 1, 0});
}

TEST(LsysTurtle, DegenerateOrUnclosedPolygonsDrawNothing) {
    EXPECT_TRUE(plantOf("Axiom: {.f.}\n").polygons.empty());
    EXPECT_TRUE(plantOf("angle: 90\nAxiom: {.f.+f.\n").polygons.empty());
    EXPECT_TRUE(plantOf("Axiom: }.F\n").polygons.empty());
}

TEST(LsysTurtle, NestedPolygonsCloseInnermostFirst) {
    const PlantAsset plant = plantOf("angle: 90\nAxiom: {.f.{.+f.+f.}f.}\n");
    ASSERT_EQ(plant.polygons.size(), 2u);
    EXPECT_EQ(plant.polygons[0].outline.size(), 3u); // the inner one closes first
    EXPECT_EQ(plant.polygons[1].outline.size(), 3u);
}

} // namespace
} // namespace lsys::test
