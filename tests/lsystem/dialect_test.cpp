// Dialect front ends: each twin file derives exactly what its native twin
// derives, and problems point at the original statement.

#include "test_support.h"

namespace lsys::test {
namespace {

std::string derivedFile(const std::string& file, int steps, uint64_t seed) {
    Grammar grammar = loadOk(file);
    DeriveOptions options = stepsOf(steps);
    options.seed = seed;
    return toString(derive(grammar, options), grammar.symbols);
}

struct Twin {
    const char* dialect;
    const char* native;
    int steps;
};

class LsysDialectTwin : public ::testing::TestWithParam<Twin> {};

TEST_P(LsysDialectTwin, DerivesTheSameAsTheNativeFile) {
    const Twin& twin = GetParam();
    for (uint64_t seed : {0ull, 1ull, 77ull})
        EXPECT_EQ(derivedFile(twin.dialect, twin.steps, seed), derivedFile(twin.native, twin.steps, seed)) << seed;
}

INSTANTIATE_TEST_SUITE_P(Crankshaw, LsysDialectTwin,
                         ::testing::Values(Twin{"plants/crankshaw_gravity_tree_2d.lsys", "plants/gravity_tree_2d.lsys", 6},
                                           Twin{"plants/crankshaw_stochastic.lsys", "plants/stochastic.lsys", 5},
                                           Twin{"plants/crankshaw_conditions.lsys", "plants/conditions.lsys", 5}));

TEST(LsysCrankshaw, ReferenceCountsOfTheGravityTree) {
    Grammar grammar = loadOk("plants/crankshaw_gravity_tree_2d.lsys");
    ModuleString string = derive(grammar);
    EXPECT_EQ(string.size(), 4608u);
    EXPECT_EQ(countOf(string, grammar, "F"), 1330u);
}

ParseOptions crankshaw() {
    ParseOptions options;
    options.dialect = Dialect::Crankshaw;
    options.file = "c.lsys";
    return options;
}

TEST(LsysCrankshaw, MultiLetterNamesAreSeparatedBySpaces) {
    Grammar grammar = parseOk("#w : Apex(1) FF F;\n#p1 : Apex(x) : * : Leaf(x) Apex(x+1);\n", crankshaw());
    EXPECT_EQ(toString(derive(grammar, stepsOf(1)), grammar.symbols), "Leaf(1)Apex(2)FFF");
    EXPECT_EQ(derive(grammar, stepsOf(1)).size(), 4u);
}

TEST(LsysCrankshaw, RangesDrawInsideTheirBounds) {
    Grammar grammar = parseOk("#n = 1;\n#w : A(0) A(0) A(0) A(0);\n#p1 : A(x) : * : B({2, 3}) C({-1, -0.5});\n", crankshaw());
    ModuleString string = derive(grammar);
    ASSERT_EQ(string.size(), 8u);
    for (size_t i = 0; i < string.size(); i += 2) {
        EXPECT_GE(string.parameters(i)[0], 2.0f);
        EXPECT_LT(string.parameters(i)[0], 3.0f);
        EXPECT_GE(string.parameters(i + 1)[0], -1.0f);
        EXPECT_LT(string.parameters(i + 1)[0], -0.5f);
    }
    EXPECT_NE(string.parameters(0)[0], string.parameters(2)[0]);  // drawn at every rewrite
}

TEST(LsysCrankshaw, ProblemsPointAtTheOriginalStatement) {
    ParseResult result = parseLsystem("#n = 2;\n#w : A;\n\n  #p1 : A : x > 1 : B;\n#p2 : A B;\nA --> B\n", crankshaw());
    ASSERT_EQ(result.diagnostics.size(), 3u);
    EXPECT_EQ(result.diagnostics[0].line, 4);
    EXPECT_EQ(result.diagnostics[0].column, 3);
    EXPECT_NE(result.diagnostics[0].message.find("unknown name 'x'"), std::string::npos);
    EXPECT_EQ(result.diagnostics[1].line, 5);
    EXPECT_NE(result.diagnostics[1].message.find("malformed production"), std::string::npos);
    EXPECT_EQ(result.diagnostics[2].line, 6);
    EXPECT_NE(result.diagnostics[2].expected.find("'#'"), std::string::npos);
}

TEST(LsysCrankshaw, StochasticGroupMustSumToOne) {
    ParseResult result = parseLsystem("#w : F;\n#p1 : F : ~0.5 : FF;\n#p2 : F : ~0.4 : F;\n", crankshaw());
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, 2);
}

INSTANTIATE_TEST_SUITE_P(Robbins, LsysDialectTwin,
                         ::testing::Values(Twin{"plants/robbins_sample_a_robbins.lsys", "plants/robbins_sample_a.lsys", 11}));

TEST(LsysRobbins, SampleAReferenceCounts) {
    Grammar grammar = loadOk("plants/robbins_sample_a_robbins.lsys");
    const std::pair<int, size_t> expected[] = {{5, 17}, {7, 53}, {9, 161}, {11, 485}};
    for (auto [steps, f] : expected) EXPECT_EQ(countOf(derive(grammar, stepsOf(steps)), grammar, "F"), f) << steps;
}

ParseOptions robbins() {
    ParseOptions options;
    options.dialect = Dialect::Robbins;
    options.file = "r.lsys";
    return options;
}

TEST(LsysRobbins, HeaderAndRenamedCommands) {
    Grammar grammar = parseOk("iterations 3 angle 12 length 2 thickness .5\nstartpoint 0 0 0 up 0 1 0\nA\nA --> F >(5) < % ; : ? A\n", robbins());
    EXPECT_EQ(grammar.derivationLength, 3);
    EXPECT_DOUBLE_EQ(grammar.angle, 12);
    EXPECT_DOUBLE_EQ(grammar.step, 2);
    EXPECT_DOUBLE_EQ(grammar.width, 0.5);
    EXPECT_EQ(toString(derive(grammar, stepsOf(1)), grammar.symbols), "F/(5)\\/(180)@Am(1.1)@Am(0.9)@Wm(1.4)A");
}

TEST(LsysRobbins, ProductionNamesMaySpanSeveralLetters) {
    Grammar grammar = parseOk("Stem\nStem --> F Leaf Stem\nLeaf --> [ + F ]\n", robbins());
    EXPECT_EQ(toString(derive(grammar, stepsOf(2)), grammar.symbols), "F[+F]FLeafStem");
}

TEST(LsysRobbins, Errors) {
    ParseResult result = parseLsystem("A\nA -->  --> B\n", robbins());
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, 2);
    EXPECT_EQ(result.diagnostics[0].column, 8);
    EXPECT_NE(result.diagnostics[0].message.find("without a production name"), std::string::npos);
    ParseResult bad = parseLsystem("A\nA --> F(2\n", robbins());
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.diagnostics[0].line, 2);
}

INSTANTIATE_TEST_SUITE_P(Plantlang, LsysDialectTwin,
                         ::testing::Values(Twin{"plants/plantlang_tree_plantlang.lsys", "plants/plantlang_tree.lsys", 12}));

ParseOptions plantlang() {
    ParseOptions options;
    options.dialect = Dialect::Plantlang;
    options.file = "p.lsys";
    return options;
}

TEST(LsysPlantlang, CommandsValuesAndReversal) {
    Grammar grammar = parseOk("Axiom = d d(2.5) d< m3 f f< f70 u u< u(10) u<10 r r< t t< t4 T T(2) c c5 l l< L0.5 + - X{.}\n", plantlang());
    EXPECT_EQ(toString(derive(grammar, stepsOf(0)), grammar.symbols),
              "FF(2.5)F(-1)f(3)/\\/(70)-+-(10)-(-10)&^@Wa@Ws!(4)@Wm(1.4)@Wm(2);;(5)@La@Ls@Lm(0.5)-+X{.}");
}

TEST(LsysPlantlang, SettingsAndRules) {
    Grammar grammar = parseOk("Axiom = F\nF => F-F++F-F\nDefault angle = 60\nDefault length = 2\nNumber of iterations = 2\n", plantlang());
    EXPECT_DOUBLE_EQ(grammar.angle, 60);
    EXPECT_DOUBLE_EQ(grammar.step, 2);
    ModuleString string = derive(grammar);
    EXPECT_EQ(string.size(), 36u);  // each F becomes 4 F and 4 turns; turns are kept
    EXPECT_EQ(countOf(string, grammar, "F"), 16u);
}

TEST(LsysPlantlang, StochasticRulesPutTheProbabilityFirst) {
    Grammar grammar = parseOk("Axiom = F\n(0.2) F -> [-F]F\n(0.2) F -> [+F]F\n(0.6) F -> FF\n", plantlang());
    ASSERT_EQ(grammar.rules.productions.size(), 3u);
    EXPECT_EQ(grammar.rules.productions[0].groupSize, 3u);
    EXPECT_DOUBLE_EQ(grammar.rules.productions[2].probability, 0.6);
    // plantlang's '-' turns left: ABOP's '+'.
    EXPECT_EQ(grammar.symbols.name(grammar.rules.productions[0].successor[1].symbol), "+");
    EXPECT_FALSE(parseLsystem("Axiom = F\n(0.2) F -> [-F]F\n(0.2) F -> FF\n", plantlang()).ok());
}

TEST(LsysPlantlang, ErrorsPointIntoTheLine) {
    ParseResult result = parseLsystem("Axiom = d\nX => d#X\nwhat\n", plantlang());
    ASSERT_EQ(result.diagnostics.size(), 2u);
    EXPECT_EQ(result.diagnostics[0].line, 2);
    EXPECT_EQ(result.diagnostics[0].column, 7);
    EXPECT_NE(result.diagnostics[0].message.find("unexpected '#'"), std::string::npos);
    EXPECT_EQ(result.diagnostics[1].line, 3);
}

TEST(LsysDialect, HeaderLineSelectsTheDialect) {
    EXPECT_TRUE(parseLsystem("// comment first\ndialect: crankshaw\n#w : A;\n").ok());
    EXPECT_FALSE(parseLsystem("#w : A;\n").ok());  // native by default: '#w' is no directive
    ParseResult unknown = parseLsystem("dialect: klingon\nAxiom: A\n");
    ASSERT_EQ(unknown.diagnostics.size(), 1u);
    EXPECT_NE(unknown.diagnostics[0].message.find("unknown dialect 'klingon'"), std::string::npos);
    EXPECT_TRUE(parseLsystem("dialect: native\nAxiom: A\n").ok());
}

}  // namespace
}  // namespace lsys::test
