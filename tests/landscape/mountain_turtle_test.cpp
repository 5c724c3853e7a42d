// The mountain turtle (lsystem/landscape/mountain_turtle.h): bumps where the
// turtle is, as high as it is above its start and as wide as its width; the
// extreme-peak rule and the bump budget; the data/terrain L-systems.
#include "lsystem/landscape/mountain_turtle.h"

#include "lsystem/language/parser.h"
#include "lsystem/vlab/object.h"

#include <gtest/gtest.h>

#include <string>

namespace lsys::landscape {
namespace {

Grammar grammarOf(const std::string& text) {
    ParseResult parsed = parseLsystem(text);
    EXPECT_TRUE(parsed.ok()) << formatDiagnostics(parsed.diagnostics, text);
    return std::move(parsed.grammar);
}

std::vector<TerrainBump> bumpsOf(const std::string& text, const MountainPlacement& placement = {}) {
    return mountainBumpsOf(grammarOf(text), placement);
}

// The message of the MountainError the text's bumps throw.
std::string errorOf(const std::string& text, const MountainPlacement& placement = {}) {
    try {
        bumpsOf(text, placement);
    } catch (const MountainError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no MountainError";
    return "";
}

void expectBump(const TerrainBump& bump, float x, float z, float height, float radius, BumpShape shape) {
    EXPECT_NEAR(bump.x, x, 1e-4f);
    EXPECT_NEAR(bump.z, z, 1e-4f);
    EXPECT_NEAR(bump.height, height, 1e-4f);
    EXPECT_NEAR(bump.radius, radius, 1e-4f);
    EXPECT_EQ(bump.shape, shape);
}

// Three steps along the core (+x), a branch up two steps, a hill there.
constexpr const char* kOneHill = "module Hill\nwidth: 4\nAxiom: f(3)[^(90)f(2)Hill]\n";

TEST(MountainTurtle, AHillSitsAtTheTurtleAsHighAsItIsAndHalfItsWidthAcross) {
    const std::vector<TerrainBump> bumps = bumpsOf(kOneHill); // 10 m a turtle unit
    ASSERT_EQ(bumps.size(), 1u);
    expectBump(bumps[0], 30.0f, 0.0f, 20.0f, 20.0f, BumpShape::Hill);
}

TEST(MountainTurtle, TheOriginScaleAndHeadingPlaceTheTurtle) {
    MountainPlacement placement;
    placement.originX = 100.0f;
    placement.originZ = -50.0f;
    placement.scale = 2.0f;
    placement.headingDegrees = 90.0f; // counter-clockwise from +x seen from above: towards -z
    const std::vector<TerrainBump> bumps = bumpsOf(kOneHill, placement);
    ASSERT_EQ(bumps.size(), 1u);
    expectBump(bumps[0], 100.0f, -56.0f, 4.0f, 4.0f, BumpShape::Hill);
}

TEST(MountainTurtle, PlusTurnsTheCoreLeftOnTheGround) {
    const std::vector<TerrainBump> bumps = bumpsOf("module Peak\nAxiom: +(90)f(2)^(90)f(1)Peak\n");
    ASSERT_EQ(bumps.size(), 1u);
    expectBump(bumps[0], 0.0f, -20.0f, 10.0f, 5.0f, BumpShape::Peak);
}

TEST(MountainTurtle, ParametersScaleHeightAndRadiusAndValleysDig) {
    const std::vector<TerrainBump> bumps =
        bumpsOf("module Hill, Mesa, Valley\nAxiom: !(2)^(90)f(1)Hill(3)Mesa(0.5, 4)Valley\n");
    ASSERT_EQ(bumps.size(), 3u);
    expectBump(bumps[0], 0.0f, 0.0f, 30.0f, 10.0f, BumpShape::Hill);
    expectBump(bumps[1], 0.0f, 0.0f, 5.0f, 40.0f, BumpShape::Mesa);
    expectBump(bumps[2], 0.0f, 0.0f, -10.0f, 10.0f, BumpShape::Valley);
}

TEST(MountainTurtle, OnlyDeclaredMountainModulesMakeBumps) {
    // Without `module Hill` the letters read H, i, l, l: no bump, no error.
    EXPECT_TRUE(bumpsOf("Axiom: ^(90)f(1)Hill\n").empty());
    EXPECT_TRUE(bumpsOf("module Hillock\nAxiom: ^(90)f(1)Hillock\n").empty());
}

TEST(MountainTurtle, ABumpPastMaxHeightIsRejectedWhereTheTurtleMadeIt) {
    MountainPlacement placement;
    placement.maxHeight = 25.0f;
    const std::string message = errorOf("module Hill, Peak\nAxiom: Hill f(4)[^(90)f(3)Peak]\n", placement);
    EXPECT_NE(message.find("Peak (module 5 of the derived word) at x 40.0 m, z 0.0 m"), std::string::npos) << message;
    EXPECT_NE(message.find("30.0 m high"), std::string::npos) << message;
    EXPECT_NE(message.find("past max_height 25.0 m"), std::string::npos) << message;
    placement.maxHeight = 30.0f; // the limit itself is allowed
    EXPECT_EQ(bumpsOf("module Hill, Peak\nAxiom: Hill f(4)[^(90)f(3)Peak]\n", placement).size(), 2u);
}

TEST(MountainTurtle, TheLimitHoldsForTheSumOfBumpsAndForDepths) {
    MountainPlacement placement;
    placement.maxHeight = 25.0f;
    // Two 20 m hills on the same spot: each within the limit, 40 m together.
    EXPECT_NE(errorOf("module Hill\nAxiom: ^(90)f(2)Hill Hill\n", placement).find("40.0 m high"), std::string::npos);
    EXPECT_NE(errorOf("module Valley\nAxiom: ^(90)f(3)Valley\n", placement).find("30.0 m deep"), std::string::npos);
}

TEST(MountainTurtle, MoreBumpsThanTheBudgetAreRefused) {
    MountainPlacement placement;
    placement.maxBumps = 2;
    const std::string message = errorOf("module Hill\nAxiom: Hill Hill Hill\n", placement);
    EXPECT_NE(message.find("more than 2 bumps (module 2 is one too many)"), std::string::npos) << message;
    placement.maxBumps = 3;
    EXPECT_EQ(bumpsOf("module Hill\nAxiom: Hill Hill Hill\n", placement).size(), 3u);
}

TEST(MountainTurtle, BadMountainParametersAreRefused) {
    EXPECT_NE(errorOf("module Hill\nAxiom: Hill(1, 2, 3)\n").find("takes at most 2 parameters"), std::string::npos);
    EXPECT_NE(errorOf("module Mesa\nAxiom: !(0)Mesa\n").find("has no width"), std::string::npos);
    MountainPlacement huge;
    huge.scale = 1e30f;
    EXPECT_NE(errorOf("module Peak\nAxiom: ^(90)f(1e10)Peak\n", huge).find("too far or too high for a float"),
              std::string::npos);
}

// A surface the word draws has no mesh folder to come from: a located
// MountainError, not a SurfaceError escaping the scene loader.
TEST(MountainTurtle, ASurfaceThatIsNotBuiltInIsAMountainError) {
    EXPECT_NE(errorOf("module Hill\nAxiom: F(1) ~ch Hill\n").find("module 1 of the mountain word: unknown surface ~ch"),
              std::string::npos);
}

TEST(MountainTurtle, AWordPastTheModuleOrMemoryBudgetIsRefused) {
    // 2^20 modules after 20 steps: past kMaxMountainModules.
    EXPECT_THROW(mountainBumpsOf(grammarOf("derivation length: 20\nAxiom: F\nF --> F F\n"), {}), ModuleBudgetError);
    const Grammar segments = grammarOf("derivation length: 6\nAxiom: F\nF --> F F\n");
    EXPECT_NO_THROW(mountainBumpsOf(segments, {}));
    EXPECT_THROW(mountainBumpsOf(segments, {}, std::nullopt, MemoryBudget{2000}), MemoryBudgetError);
}

// data/terrain: the ridge, valley and massif the scenes use.
Grammar dataGrammar(const std::string& name) {
    vlab::PlantFile file = vlab::loadPlant(std::string(PLANTFIELD_DATA_DIR) + "/terrain/" + name);
    EXPECT_TRUE(file.parsed.ok()) << formatDiagnostics(file.parsed.diagnostics, file.source);
    return std::move(file.parsed.grammar);
}

TEST(MountainTurtle, TheDataMountainsAreDeterministicAndWithinTheirLimit) {
    for (const char* name : {"ridge.lsys", "valley.lsys", "massif.lsys"}) {
        SCOPED_TRACE(name);
        const Grammar grammar = dataGrammar(name);
        const std::vector<TerrainBump> first = mountainBumpsOf(grammar, {}, 7),
                                       second = mountainBumpsOf(grammar, {}, 7);
        ASSERT_GT(first.size(), 10u);
        EXPECT_EQ(first, second); // bit for bit: TerrainBump compares its floats exactly
        float highest = 0.0f;
        for (const TerrainBump& bump : first)
            highest = std::max(highest, std::abs(bumpsHeightAt(first, bump.x, bump.z)));
        EXPECT_LE(highest, MountainPlacement{}.maxHeight);
        EXPECT_GT(highest, 10.0f);
    }
}

TEST(MountainTurtle, AnotherSeedMakesAnotherMassif) {
    const Grammar grammar = dataGrammar("massif.lsys");
    EXPECT_NE(mountainBumpsOf(grammar, {}, 1), mountainBumpsOf(grammar, {}, 2));
}

} // namespace
} // namespace lsys::landscape
