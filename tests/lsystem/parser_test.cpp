// The .lsys parser: header settings, module names, sections, and diagnostics
// (file:line:column, caret, what was expected) for malformed input.

#include <random>

#include "test_support.h"

namespace lsys::test {
namespace {

TEST(LsysParser, HeaderSettings) {
    Grammar grammar = parseOk("/* a block comment\n spanning lines */\n"
                              "#define N 3 // trailing comment\n"
                              "#define half N/2\n"
                              "seed: 42\n"
                              "derivation length: N+1\n"
                              "angle: 22.5\n"
                              "step: half\n"
                              "width: 0.1\n"
                              "Axiom: F(N)\n"
                              "F(x) -> F(x+half)\n"
                              "endlsystem\n"
                              "anything after endlsystem is ignored\n");
    EXPECT_EQ(grammar.seed, 42u);
    EXPECT_EQ(grammar.derivationLength, 4);
    EXPECT_DOUBLE_EQ(grammar.angle, 22.5);
    EXPECT_DOUBLE_EQ(grammar.step, 1.5);
    EXPECT_DOUBLE_EQ(grammar.width, 0.1);
    EXPECT_EQ(toString(derive(grammar), grammar.symbols), "F(9)");
}

TEST(LsysParser, HeadersAreCaseInsensitive) {
    Grammar grammar = parseOk("AXIOM: A\nDerivation Length: 2\nA --> AB\n");
    EXPECT_EQ(toString(derive(grammar), grammar.symbols), "ABB");
}

TEST(LsysParser, DefinesCanBeOverridden) {
    ParseOptions options;
    options.defines["N"] = 7;
    options.defines["EXTRA"] = 2;
    Grammar grammar = parseOk("#define N 3\nAxiom: A(N, EXTRA)\n", options);
    EXPECT_EQ(toString(derive(grammar, stepsOf(0)), grammar.symbols), "A(7,2)");
}

TEST(LsysParser, SingleCharacterModules) {
    EXPECT_EQ(derive(parseOk("Axiom: F1F1F1\n"), stepsOf(0)).size(), 6u);
    EXPECT_EQ(derive(parseOk("Axiom: BA[A]\n"), stepsOf(0)).size(), 5u);
    EXPECT_EQ(derive(parseOk("Axiom: +-&^\\/|$!;'%~.{}\n"), stepsOf(0)).size(), 16u);
}

TEST(LsysParser, DeclaredMultiLetterModules) {
    Grammar grammar =
        parseOk("module Apex, Leaf(size)\nmodule Ap\nAxiom: Apex(1)ApLeafA\nApex(x) --> Leaf(x) Apex(x+1)\n");
    EXPECT_EQ(toString(derive(grammar, stepsOf(1)), grammar.symbols), "Leaf(1)Apex(2)ApLeafA");
    EXPECT_EQ(derive(grammar, stepsOf(1)).size(), 5u);
}

TEST(LsysParser, PrefixedModuleNames) {
    Grammar grammar = parseOk("Axiom: @O(1)@Ts(0.2)~leaf(3)\n");
    ModuleString string = derive(grammar, stepsOf(0));
    ASSERT_EQ(string.size(), 3u);
    EXPECT_EQ(grammar.symbols.name(string.symbols[0]), "@O");
    EXPECT_EQ(grammar.symbols.name(string.symbols[1]), "@Ts");
    EXPECT_EQ(grammar.symbols.name(string.symbols[2]), "~leaf");
    // cpfg's: one lower-case letter (two after @m and @b), or one of # ! ; , after the '@'.
    Grammar cpfg = parseOk("Axiom: @o(1)@cF@mo@bcf@#(2)@!@;@,#,\n");
    std::vector<std::string> names;
    for (SymbolId symbol : derive(cpfg, stepsOf(0)).symbols) names.push_back(cpfg.symbols.name(symbol));
    EXPECT_EQ(names, (std::vector<std::string>{"@o", "@c", "F", "@mo", "@bc", "f", "@#", "@!", "@;", "@,", "#", ","}));
}

// cpfg's preprocessor passes a line that begins with '#' but no directive
// on as text; natively too such a line with an arrow is a production.
TEST(LsysParser, ALineBeginningWithHashIsAProductionOfTheWidthModule) {
    EXPECT_EQ(derived("Axiom: #(1) #\n#(w) --> #(w + 1)\n  # --> #(1)\n", 2), "#(3)#(2)");
}

// Headers that choose one of two ways: the first is the default.
TEST(LsysParser, ChoiceHeadersSetTheirWay) {
    const Grammar native = parseOk("Axiom: A\n");
    const Grammar chosen = parseOk("arithmetic: cpfg\ncut: next step\ndecompose axiom: no\nturtle modules: cpfg\n"
                                   "Axiom: A\n");
    EXPECT_EQ(native.arithmetic, Arithmetic::Native);
    EXPECT_EQ(chosen.arithmetic, Arithmetic::Cpfg);
    EXPECT_FALSE(native.cutInNextStep);
    EXPECT_TRUE(chosen.cutInNextStep);
    EXPECT_TRUE(native.decomposeAxiom);
    EXPECT_FALSE(chosen.decomposeAxiom);
    EXPECT_FALSE(native.style.cpfgModules);
    EXPECT_TRUE(chosen.style.cpfgModules);
}

TEST(LsysParser, LabelsAndStarCondition) {
    EXPECT_EQ(derived("Axiom: A(1)\np1: A(x) : * --> B(x)\np2 : B(x) : x > 0 -> C\n", 2), "C");
}

TEST(LsysParser, EmptySuccessor) { EXPECT_EQ(derived("Axiom: ABA\nA -->\nB --> *\n", 1), ""); }

TEST(LsysParser, SectionsAndMaximumDepth) {
    Grammar grammar = parseOk("Axiom: A\nA --> AS\n"
                              "decomposition:\nmaximum depth: 5\nS --> T\nT --> U\n"
                              "homomorphism: maximum depth: 3000\nU --> F\n");
    EXPECT_EQ(grammar.decomposition.productions.size(), 2u);
    EXPECT_EQ(grammar.decomposition.maxDepth, 5);
    EXPECT_EQ(grammar.interpretation.productions.size(), 1u);
    EXPECT_EQ(grammar.interpretation.maxDepth, 3000); // vlab's LilyLeaf asks for 3000
}

TEST(LsysParser, EveryProblemIsReported) {
    ParseResult result = parseLsystem("Axiom: A(\nA -> B(\nC --> D\nwhat is this\n", {"bad.lsys"});
    ASSERT_EQ(result.diagnostics.size(), 3u);
    EXPECT_EQ(result.diagnostics[0].line, 1);
    EXPECT_EQ(result.diagnostics[1].line, 2);
    EXPECT_EQ(result.diagnostics[2].line, 4);
}

TEST(LsysParser, DiagnosticFormat) {
    const std::string source = "Axiom: A\nA(x) --> B(x +* 2)\n";
    ParseResult result = parseLsystem(source, {"plant.lsys"});
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(
        formatDiagnostic(result.diagnostics[0], source),
        "plant.lsys:2:15: error: unexpected '*' in expression (expected a number, a name, '(' or a unary operator)\n"
        "  A(x) --> B(x +* 2)\n"
        "                ^\n");
}

TEST(LsysParser, ALongLineIsShownAroundTheColumnOnly) {
    const std::string source = "Axiom: A " + std::string(100000, 'F') + " (\n";
    ParseResult result = parseLsystem(source, {"long.lsys"});
    ASSERT_EQ(result.diagnostics.size(), 1u);
    const std::string text = formatDiagnostic(result.diagnostics[0], source);
    EXPECT_LT(text.size(), 400u) << text.substr(0, 400);
    // The line as shown: "...", the 80 characters before the '(' and it.
    const std::string shown = "  ..." + std::string(79, 'F') + " (\n";
    EXPECT_NE(text.find(shown), std::string::npos) << text.substr(0, 400);
    EXPECT_NE(text.find("\n" + std::string(2 + 3 + 80, ' ') + "^\n"), std::string::npos) << text.substr(0, 400);
}

TEST(LsysParser, ManyErrorsAreCountedPastTheFirstHundred) {
    std::string source = "Axiom: A\n";
    for (int i = 0; i < 250; ++i) source += "A --> B(\n";
    ParseResult result = parseLsystem(source, {"many.lsys"});
    ASSERT_EQ(result.diagnostics.size(), 250u);
    const std::string text = formatDiagnostics(result.diagnostics, source);
    EXPECT_NE(text.find("many.lsys:101:"), std::string::npos);
    EXPECT_EQ(text.find("many.lsys:102:"), std::string::npos);
    EXPECT_NE(text.find("many.lsys: 150 more errors not shown (250 in all)"), std::string::npos);
}

struct Malformed {
    const char* source;
    int line;
    int column;
    const char* message;
};

class LsysMalformedInput : public ::testing::TestWithParam<Malformed> {};

TEST_P(LsysMalformedInput, IsReportedAtTheRightPlace) {
    const Malformed& c = GetParam();
    ParseResult result = parseLsystem(c.source, {"m.lsys"});
    ASSERT_FALSE(result.diagnostics.empty()) << c.source;
    const Diagnostic& first = result.diagnostics[0];
    EXPECT_EQ(first.file, "m.lsys");
    EXPECT_EQ(first.line, c.line) << c.source;
    EXPECT_EQ(first.column, c.column) << c.source;
    EXPECT_NE(first.message.find(c.message), std::string::npos) << first.message;
}

INSTANTIATE_TEST_SUITE_P(
    Parser, LsysMalformedInput,
    ::testing::Values(Malformed{"A --> B\n", 1, 1, "no axiom"},
                      Malformed{"Axiom: A\nA [B --> C\n", 2, 6, "brackets are not allowed in a strict predecessor"},
                      Malformed{"Axiom: A\nA < < B --> C\n", 2, 5, "misplaced '<'"},
                      Malformed{"Axiom: A\nA > B > C --> D\n", 2, 7, "second '>'"},
                      Malformed{"Axiom: A\nB[C] < A --> D\n", 2, 6, "brackets are not allowed in a left context"},
                      Malformed{"Axiom: A\nA(1) --> B\n", 2, 3, "must be a name"},
                      Malformed{"Axiom: A\nA(x) --> B(y)\n", 2, 12, "unknown name 'y'"},
                      Malformed{"Axiom: A\nA : x > 1 --> B\n", 2, 5, "unknown name 'x'"},
                      Malformed{"Axiom: A\nA(x) : x > 1 B\n", 2, 1, "unrecognised line"},
                      Malformed{"Axiom: A\nA --> B(1,)\n", 2, 11, "expression"},
                      Malformed{"Axiom: A\nA --> B(1 2)\n", 2, 11, "malformed parameter list"},
                      Malformed{"Axiom: A\nA --> B : 1.5\n", 2, 11, "probability out of range"},
                      Malformed{"Axiom: A\nA --> B <\n", 2, 9, "unexpected '<'"},
                      Malformed{"Axiom: A\n#include foo\n", 2, 1, "unknown directive"},
                      Malformed{"Axiom: A\ncut: never\n", 2, 6, "unknown cut setting"},
                      Malformed{"Axiom: A\ndecompose axiom: maybe\n", 2, 18, "unknown decompose axiom setting"},
                      Malformed{"Axiom: A\nturtle modules: lpfg\n", 2, 17, "unknown turtle modules setting"},
                      Malformed{"Axiom: A\n#define\n", 2, 8, "missing constant name"},
                      Malformed{"Axiom: A\nseed: -1\n", 2, 7, "invalid seed"},
                      Malformed{"Axiom: A\nderivation length: 2.5\n", 2, 20, "invalid derivation length"},
                      Malformed{"Axiom: A\nmaximum depth: 3\n", 2, 16, "outside a decomposition"},
                      Malformed{"Axiom: A\nhomomorphism:\nmaximum depth: 10001\n", 3, 16, "invalid maximum depth"},
                      Malformed{"Axiom: A\nangle: 10 20\n", 2, 11, "unexpected '2'"},
                      Malformed{"Axiom: A /* never closed\n", 1, 10, "unterminated comment"},
                      Malformed{"Axiom: A\nmodule 3D\n", 2, 8, "unexpected '3'"},
                      Malformed{"Axiom: A\nignore: + ( -\n", 2, 11, "unexpected '('"}));

TEST(LsysParser, GarbageNeverCrashesOrHangs) {
    // A small deterministic fuzz: random mixtures of the language's characters and random bytes.
    const std::string alphabet = "AB F(x)y,:<>-->[]+*/^%!?&|\n#define axiom: 0123.e \t\\'\"{}~@$;";
    std::mt19937 random(1234);
    for (int round = 0; round < 3000; ++round) {
        std::string source;
        const int length = static_cast<int>(random() % 200);
        for (int i = 0; i < length; ++i)
            source += (random() % 8 == 0) ? static_cast<char>(random() % 256) : alphabet[random() % alphabet.size()];
        ParseResult result = parseLsystem(source);
        if (result.ok()) {
            DeriveOptions options = stepsOf(3);
            options.maxModules = 10000;
            try {
                derive(result.grammar, options);
            } catch (const DerivationError&) {}
        }
    }
}

} // namespace
} // namespace lsys::test
