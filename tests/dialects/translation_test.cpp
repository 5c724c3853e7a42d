// What each dialect construct becomes: derived strings of small systems.

#include "dialect_test_support.h"

namespace lsys::test {
namespace {

std::string derived(Dialect dialect, const std::string& source, int steps, uint64_t seed = 0) {
    Grammar grammar = parseOk(dialect, source);
    return toString(deriveSteps(grammar, steps, seed), grammar.symbols);
}

TEST(Crankshaw, SeveralStatementsOnOneLine) {
    Grammar grammar =
        parseOk(Dialect::Crankshaw, "#n = 3; #define a 2; #define b a * 3;\n#w : A(b); #p1 : A(x) : * : A(x + a);\n");
    EXPECT_EQ(grammar.derivationLength, 3);
    EXPECT_EQ(toString(deriveSteps(grammar, 3), grammar.symbols), "A(12)");
}

TEST(Crankshaw, MultiLetterNamesAreSeparatedBySpaces) {
    // FX is one module; F X two. Declared even when first used in a production before the axiom.
    Grammar tree = parseOk(Dialect::Crankshaw, "#p1 : FX : * : F X FX;\n#w : FX;\n");
    ModuleString string = deriveSteps(tree, 2); // F X F X FX
    EXPECT_EQ(string.size(), 5u);
    EXPECT_EQ(countsOf(string, tree), (std::map<std::string, size_t>{{"F", 2}, {"X", 2}, {"FX", 1}}));
    Grammar grammar = parseOk(Dialect::Crankshaw, "#w : apex leaf_2 F;\n");
    EXPECT_EQ(deriveSteps(grammar, 0).size(), 3u);
}

TEST(Crankshaw, SpaceBeforeParametersBelongsToTheModule) {
    EXPECT_EQ(derived(Dialect::Crankshaw, "#w : F - (30) F +  (2)Z;", 0), "F-(30)F+(2)Z");
}

TEST(Crankshaw, LiteralPredecessorParameterBecomesACondition) {
    // As printed in eq 7.1: F(1, sc) matches only a first parameter of 1.
    EXPECT_EQ(derived(Dialect::Crankshaw,
                      "#w : F(1, 5) F(2, 5) F(-1, 5);\n#p : F(1, sc) : * : F(3, sc);\n#q : F(-1, sc) : sc > 4 : G;", 1),
              "F(3,5)F(2,5)G");
}

TEST(Crankshaw, StochasticAlternativesWithALiteralFormOneGroup) {
    std::string string = derived(
        Dialect::Crankshaw,
        "#w : F(1) F(1) F(1) F(1) F(1) F(1) F(1) F(1) F(2);\n#p1 : F(1) : ~0.5 : A;\n#p2 : F(1) : ~0.5 : B;", 1, 2);
    EXPECT_EQ(string.size(), 12u) << string; // eight A or B, and F(2) untouched
    EXPECT_NE(string.find('A'), std::string::npos);
    EXPECT_NE(string.find('B'), std::string::npos);
    EXPECT_NE(string.find("F(2)"), std::string::npos);
}

TEST(Crankshaw, ConditionsAndStochasticChoice) {
    EXPECT_EQ(derived(Dialect::Crankshaw, "#w : A(1) A(5);\n#p1 : A(x) : x >= 5 : B;\n#p2 : A(x) : * : C(x);", 1),
              "C(1)B");
    std::string string =
        derived(Dialect::Crankshaw,
                "#w : A A A A A A A A A A A A A A A A A A A A;\n#p1 : A : ~0.5 : B;\n#p2 : A : ~0.5 : C;", 1, 5);
    EXPECT_EQ(string.size(), 20u);
    EXPECT_NE(string.find('B'), std::string::npos);
    EXPECT_NE(string.find('C'), std::string::npos);
    EXPECT_EQ(string.find('A'), std::string::npos);
}

TEST(Crankshaw, RangesAreDrawnOnceInDefinesAndPerEvaluationInSuccessors) {
    Grammar grammar =
        parseOk(Dialect::Crankshaw,
                "#define r {10, 20};\n#define s {7};\n#w : A A A A A A A A;\n#p1 : A : * : B({-1, 1}) C(r) D(s);\n");
    ASSERT_TRUE(grammar.constants.contains("r"));
    double r = grammar.constants.at("r");
    EXPECT_GE(r, 10.0);
    EXPECT_LT(r, 20.0);
    EXPECT_DOUBLE_EQ(grammar.constants.at("s"), 7.0);
    ModuleString string = deriveSteps(grammar, 1, 3);
    std::set<float> drawn;
    for (size_t i = 0; i < string.size(); ++i) {
        const std::string& name = grammar.symbols.name(string.symbols[i]);
        float value = string.parameters(i)[0];
        if (name == "B") {
            EXPECT_GE(value, -1.0f);
            EXPECT_LT(value, 1.0f);
            drawn.insert(value);
        }
        if (name == "C") {
            EXPECT_FLOAT_EQ(value, static_cast<float>(r));
        }
        if (name == "D") {
            EXPECT_FLOAT_EQ(value, 7.0f);
        }
    }
    EXPECT_EQ(drawn.size(), 8u); // a fresh draw for every B
}

TEST(Crankshaw, SpringConstantAndRingResolutionGoToTheTurtleThroughInterpretation) {
    Grammar grammar = parseOk(Dialect::Crankshaw, "#w : !(0.5, 8) F(0.4, 30) F(2);");
    ModuleString string = deriveSteps(grammar, 0);
    EXPECT_EQ(toString(string, grammar.symbols), "!(0.5,8)F(0.4,30)F(2)");
    EXPECT_EQ(toString(applyInterpretation(grammar, string), grammar.symbols), "!(0.5)@K(30)F(0.4)F(2)");
}

TEST(Robbins, SymbolsBecomeNativeModules) {
    std::string source = "iterations 1 angle 20 length 2 thickness .5\n"
                         "X\n"
                         "X --> \" ' \"(2) '(3) ; : ;(4) ?\n"
                         "  ! ?(5) !(6) t t(.3) % < >(9) | $ { F } [ f ] + - & ^ LongName\n";
    Grammar grammar = parseOk(Dialect::Robbins, source);
    EXPECT_EQ(grammar.derivationLength, 1);
    EXPECT_DOUBLE_EQ(grammar.angle, 20);
    EXPECT_DOUBLE_EQ(grammar.step, 2);
    EXPECT_DOUBLE_EQ(grammar.width, 0.5);
    EXPECT_EQ(toString(deriveSteps(grammar, 1), grammar.symbols),
              "@Lm(1.1)@Lm(0.9)@Lm(2)@Lm(3)@Am(1.1)@Am(0.9)@Am(4)@Wm(1.4)@Wm(0.7)@Wm(5)@Wm(6)@Ts(0.2)@Ts(0.3)/(180)\\/"
              "(9)|$[{F}][f]+-&^LongName");
}

TEST(Robbins, FreeFormProductionsEndAtTheNextName) {
    EXPECT_EQ(derived(Dialect::Robbins, "angle 30 A B A --> B B B --> [ + A ] B", 1), "BB[+A]B");
    EXPECT_EQ(derived(Dialect::Robbins, "FP A\nA --> FP\n  A\nFP --> F F\n", 2), "FFFFFPA");
}

TEST(Plantlang, EveryCommand) {
    std::string source =
        "Default length = 2\nlength increment = 0.5\nlength factor = 0.8\nangle increment = 5\nangle factor = 2\n"
        "thickness increment = 3\nthickness factor = 4\n"
        "Axiom = d d< d(3) D(50) m m< m4 M(50) f f< f(10) u u< u7 r r< r(8) + - t t< t(2) T T< T2 "
        "o o< O(2) c c< c(4) a a< a(10) A A< A(2) l l< l(3) L L< L0.5 X [ ] { . } F\n";
    EXPECT_EQ(derived(Dialect::Plantlang, source, 0),
              "FF(-2)F(3)F(1)ff(-2)f(4)f(1)/\\/(10)-+-(7)&^&(8)-+@Wa(3)@Wa(-3)!(2)@Wm(4)@Wm(0.25)@Wm(2)"
              "@O@Oc@O(2);@Ca(-1);(4)@Aa(5)@Aa(-5)@As(10)@Am(2)@Am(0.5)@Am(2)@La(0.5)@La(-0.5)@Ls(3)@Lm(0.8)@Lm(1.25)@"
              "Lm(0.5)X[]{.}F");
}

TEST(Plantlang, SettingsProductionsAndProbabilities) {
    Grammar grammar = parseOk(Dialect::Plantlang, "Axiom: X\nX => dY\n(0.5) Y -> +\n(0.5) Y -> -\nDefault angle = "
                                                  "60\nDefault thickness = 3\nIterations = 4\nSeed = 9\n");
    EXPECT_DOUBLE_EQ(grammar.angle, 60);
    EXPECT_DOUBLE_EQ(grammar.width, 3);
    EXPECT_EQ(grammar.derivationLength, 4);
    EXPECT_EQ(grammar.seed, 9u);
    std::string string = toString(deriveSteps(grammar, 2, 1), grammar.symbols);
    EXPECT_TRUE(string == "F-" || string == "F+") << string;
}

TEST(Plantlang, PredecessorsTranslateLikeSuccessors) {
    // '+' is '-' natively, and d is F: a rule for d rewrites F.
    EXPECT_EQ(derived(Dialect::Plantlang, "Axiom = +d\n+ => ++\nd => dm\n", 1), "--Ff");
}

} // namespace
} // namespace lsys::test
