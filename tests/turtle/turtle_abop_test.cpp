// The turtle against ABOP: Koch curves, a 3D branch worked out by hand,
// turning around, rolling to horizontal and tropism (ABOP §1.5, §2.4).

#include <cmath>

#include "turtle_test_support.h"

namespace lsys::test {
namespace {

// ABOP Fig 1.9a: the quadratic Koch curve F -> F+F-F-F+F keeps its end
// 3^n steps straight ahead after n steps, through 5^n segments.
TEST(LsysTurtleAbop, KochCurveEndsStraightAhead) {
    ParseResult parsed = parseLsystem("angle: 90\nAxiom: F\nF --> F+F-F-F+F\n");
    ASSERT_TRUE(parsed.ok());
    for (int steps = 1; steps <= 4; ++steps) {
        SCOPED_TRACE(steps);
        DeriveOptions options;
        options.steps = steps;
        const std::vector<Span> spans = spansOf(plantFromGrammar(parsed.grammar, derive(parsed.grammar, options)));
        ASSERT_EQ(spans.size(), static_cast<size_t>(std::pow(5, steps)));
        expectNear(spans.back().end, {0, std::pow(3.0f, static_cast<float>(steps)), 0}, 1e-3f);
        for (const Span& span : spans) ASSERT_NEAR(span.start.z, 0.0f, 1e-5f); // a plane curve
    }
}

// The quadratic Koch island (ABOP Fig 1.7a) closes: its last segment ends at the start.
TEST(LsysTurtleAbop, KochIslandCloses) {
    const std::vector<Span> spans = spansOf("angle: 90\nderivation length: 2\nAxiom: F-F-F-F\nF --> F-F+F+FF-F-F+F\n");
    ASSERT_EQ(spans.size(), 4u * 64u);
    expectNear(spans.back().end, {0, 0, 0}, 1e-3f);
}

// Worked out by hand from H = +Y, L = -X, U = +Z:
//   F(1)   -> (0,1,0)
//   &(90)  pitch down: H = -U = (0,0,-1), U = (0,1,0)
//   F(2)   -> (0,1,-2)
//   /(90)  roll right: L = (0,-1,0), U = (-1,0,0)
//   +(90)  yaw towards L: H = (0,-1,0)
//   F(3)   -> (0,-2,-2)
//   ^(90)  pitch up: H = U = (-1,0,0)
//   F(4)   -> (-4,-2,-2)
TEST(LsysTurtleAbop, ThreeDimensionalPathWorkedOutByHand) {
    const std::vector<Span> spans = spansOf("Axiom: F(1)&(90)F(2)/(90)+(90)F(3)^(90)F(4)\n");
    ASSERT_EQ(spans.size(), 4u);
    expectNear(spans[1].end, {0, 1, -2});
    expectNear(spans[2].end, {0, -2, -2});
    expectNear(spans[3].end, {-4, -2, -2});
}

TEST(LsysTurtleAbop, BranchesInThreeDimensions) {
    const std::vector<Span> spans = spansOf("angle: 90\nAxiom: F[&F][/&F][\\&F]F\n");
    ASSERT_EQ(spans.size(), 5u);
    expectNear(spans[1].end, {0, 1, -1});
    expectNear(spans[2].end, {1, 1, 0});  // rolled right, down points to +X
    expectNear(spans[3].end, {-1, 1, 0}); // rolled left, down points to -X
    expectNear(spans[4].end, {0, 2, 0});
}

TEST(LsysTurtleAbop, TurnAroundReversesHeadingAndLeftKeepsUp) {
    const PlantAsset plant = plantOf("Axiom: F|F|F\n");
    const std::vector<Span> spans = spansOf(plant);
    ASSERT_EQ(spans.size(), 3u);
    expectNear(spans[1].end, {0, 0, 0});
    expectNear(spans[2].end, {0, 1, 0});
    const Frame& turned = plant.primitives[1].frame;
    expectNear(leftOf(turned), {1, 0, 0});
    expectNear(turned.rotation * glm::vec3(0, 0, 1), {0, 0, 1});
}

TEST(LsysTurtleAbop, RollToHorizontalLeavesLHorizontalAndHUnchanged) {
    for (const char* turns : {"&(30)+(20)/(50)", "^(70)\\(33)-(10)", "+(90)&(45)/(30)"}) {
        SCOPED_TRACE(turns);
        const PlantAsset plant = plantOf(std::string("Axiom: ") + turns + "F$F\n");
        ASSERT_EQ(plant.primitives.size(), 2u);
        const Frame& before = plant.primitives[0].frame;
        const Frame& after = plant.primitives[1].frame;
        expectNear(headingOf(after), headingOf(before));
        EXPECT_NEAR(leftOf(after).y, 0.0f, 1e-5f);
        EXPECT_GT(std::abs(leftOf(before).y), 0.01f); // the roll did something
        // ABOP: L = V x H / |V x H|, so U points upwards.
        EXPECT_GE((after.rotation * glm::vec3(0, 0, 1)).y, 0.0f);
    }
}

// The angle between the heading of segment i and the tropism vector T.
float angleToTropism(const Span& span, glm::vec3 tropism) {
    return std::acos(glm::dot(glm::normalize(span.end - span.start), glm::normalize(tropism)));
}

TEST(LsysTurtleAbop, TropismTurnsTheHeadingByElasticityTimesSine) {
    // Horizontal start, T = (0,-1,0): |H x T| = 1, so the second segment dips by e radians.
    const float e = 0.3f;
    const std::vector<Span> spans = spansOf("Axiom: +(90)@Ts(0.3)FF\n");
    ASSERT_EQ(spans.size(), 2u);
    expectNear(spans[0].end, {-1, 0, 0});
    expectNear(spans[1].end - spans[1].start, {-std::cos(e), -std::sin(e), 0});
}

TEST(LsysTurtleAbop, TropismBendsMoreForLargerElasticity) {
    auto finalAngle = [](const std::string& elasticity) {
        const std::vector<Span> spans = spansOf("Axiom: +(60)@Ts(" + elasticity + ")FFFFF\n");
        return angleToTropism(spans.back(), {0, -1, 0});
    };
    const float none = finalAngle("0");
    const float some = finalAngle("0.1");
    const float more = finalAngle("0.3");
    EXPECT_NEAR(none, glm::radians(120.0f), 1e-4f); // H starts 60 degrees from +Y
    EXPECT_LT(some, none);
    EXPECT_LT(more, some);
}

TEST(LsysTurtleAbop, TropismVectorCanBeSetAndOnlySegmentsBend) {
    const std::vector<Span> spans = spansOf("Axiom: @Tv(1,0,0)@Ts(0.2)ffF[F]f(0)F\n");
    ASSERT_EQ(spans.size(), 3u);
    expectNear(spans[0].start, {0, 2, 0}); // f does not bend
    expectNear(spans[1].end - spans[1].start, {std::sin(0.2f), std::cos(0.2f), 0});
    expectNear(spans[2].start, spans[1].start); // the branch was popped
    expectNear(spans[2].end - spans[2].start, {std::sin(0.2f), std::cos(0.2f), 0});
}

TEST(LsysTurtleAbop, TropismFromTheSettings) {
    ParseResult parsed = parseLsystem("Axiom: +(90)FF\n");
    ASSERT_TRUE(parsed.ok());
    TurtleSettings settings = turtleSettings(parsed.grammar);
    settings.elasticity = 0.3f;
    settings.tropism = {0, 1, 0};
    const std::vector<Span> spans =
        spansOf(interpretPlant(derive(parsed.grammar), parsed.grammar.symbols, settings, SurfaceLibrary{}));
    ASSERT_EQ(spans.size(), 2u);
    expectNear(spans[1].end - spans[1].start, {-std::cos(0.3f), std::sin(0.3f), 0});
}

// cpfg's bend (interpret.c, bend) for cpfg files: H turns toward U by
// asin(e T.U), then toward L by asin(e T.L), where ABOP turns it by e|H x T|
// toward T. With T = (1,0,1) and e = 0.5 the two turns have sines 0.5 and
// -0.5 (L = -X): H = (0, cos 30, sin 30), then cos 30 H - 0.5 L.
// The segments of `source` drawn with an elasticity of 0.5 from the start,
// as a view file's "initial elasticity: 0.5" gives it.
std::vector<Span> spansWithElasticity(const std::string& source) {
    Grammar grammar = parseOk(source);
    grammar.style.elasticity = 0.5;
    return spansOf(plantFromGrammar(grammar, derive(grammar)));
}

TEST(LsysTurtleAbop, CpfgFilesBendAsCpfg) {
    const float c = std::sqrt(0.75f);
    std::vector<Span> spans = spansWithElasticity("turtle modules: cpfg\nAxiom: @Tv(1,0,0)FF\n");
    ASSERT_EQ(spans.size(), 2u);
    expectNear(spans[1].end - spans[1].start, {0.5f, c, 0});
    spans = spansOf("Axiom: @Tv(1,0,0)@Ts(0.5)FF\n");
    expectNear(spans.at(1).end - spans[1].start, {std::sin(0.5f), std::cos(0.5f), 0});
    // Toward U first, then toward L (the other order would end at (c/2, 0.75, 0.5)).
    spans = spansWithElasticity("turtle modules: cpfg\nAxiom: @Tv(1,0,1)FF\n");
    expectNear(spans.at(1).end - spans[1].start, {0.5f, 0.75f, 0.5f * c});
}

// In cpfg files @Ts(k, e) sets the k-th movement's elasticity (blackbox.c),
// never the elasticity of "tropism direction:": without movements it
// changes nothing, and the plant stays straight.
TEST(LsysTurtleAbop, CpfgFilesSetMovementsWithAtTs) {
    const std::vector<Span> spans = spansOf("turtle modules: cpfg\nAxiom: @Tv(1,0,0)@Ts(0.5)@Ts(1,0.5)FF\n");
    ASSERT_EQ(spans.size(), 2u);
    expectNear(spans[1].end - spans[1].start, {0, 1, 0});
}

// A movement turns the heading before the segment, by the elasticity @Ti,
// @Td and @Ts leave it: an orthotropism toward +X of elasticity e turns the
// upright heading by e radians (|H x eT| = e).
TEST(LsysTurtleAbop, MovementsTurnBeforeEachStepByTheirElasticity) {
    Grammar grammar = parseOk("turtle modules: cpfg\nAxiom: F @Ti(1) F @Td(1,0.1) F [@Ts(1,0) F] F\n");
    grammar.style.movements = {Movement{MovementKind::Tropism, {1, 0, 0}, 0.0f, 0.2f, 0.1f}};
    const std::vector<Span> spans = spansOf(plantFromGrammar(grammar, derive(grammar)));
    ASSERT_EQ(spans.size(), 5u);
    const auto turned = [](float angle) { return glm::vec3(std::sin(angle), std::cos(angle), 0.0f); };
    expectNear(spans[0].end - spans[0].start, turned(0.2f));
    expectNear(spans[1].end - spans[1].start, turned(0.2f + 0.3f * std::cos(0.2f)), 1e-4f);
    EXPECT_GT(spans[1].end.x - spans[1].start.x, spans[0].end.x - spans[0].start.x);
    // e = 0 in the branch: no turn; after it e = 0.2 again, and the heading turns further.
    expectNear(spans[3].end - spans[3].start, spans[2].end - spans[2].start, 1e-5f);
    EXPECT_GT(spans[4].end.x - spans[4].start.x, spans[2].end.x - spans[2].start.x + 1e-3f);
}

TEST(LsysTurtleAbop, HeadingAlongTropismDoesNotBend) {
    const std::vector<Span> spans = spansOf("Axiom: |@Ts(0.5)FF\n");
    ASSERT_EQ(spans.size(), 2u);
    expectNear(spans[1].end, {0, -2, 0});
}

} // namespace
} // namespace lsys::test
