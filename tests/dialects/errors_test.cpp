// Malformed dialect input: every problem is reported at its line and column in
// the original file (also those the native parser finds in the translation),
// and no input crashes or hangs the translators.

#include <random>

#include "dialect_test_support.h"

namespace lsys::test {
namespace {

struct ErrorCase {
    Dialect dialect;
    const char* source;
    int line;
    int column;
    const char* message; // a part of the first diagnostic's message
};

class DialectErrors : public ::testing::TestWithParam<ErrorCase> {};

// Each of 200 000 errors at its own line: positions are mapped back to the
// source in one pass (once per error, this took minutes).
TEST(DialectErrorPositions, EveryOneOfManyErrorsKeepsItsLine) {
    std::string source = "Axiom: A\n";
    constexpr int kErrors = 200000;
    for (int i = 0; i < kErrors; ++i) source += "A --> B(\n";
    const ParseResult result = parseDialect(std::nullopt, source, {"many"});
    ASSERT_EQ(result.diagnostics.size(), size_t(kErrors));
    for (int i = 0; i < kErrors; i += 9973) EXPECT_EQ(result.diagnostics[size_t(i)].line, i + 2);
    EXPECT_EQ(result.diagnostics.back().line, kErrors + 1);
}

TEST_P(DialectErrors, ReportedAtTheOriginalPosition) {
    const ErrorCase& c = GetParam();
    ParseResult result = parseDialect(c.dialect, c.source, {"bad"});
    ASSERT_FALSE(result.diagnostics.empty());
    const Diagnostic& first = result.diagnostics.front();
    EXPECT_EQ(first.file, "bad");
    EXPECT_EQ(first.line, c.line) << first.message;
    EXPECT_EQ(first.column, c.column) << first.message;
    EXPECT_NE(first.message.find(c.message), std::string::npos) << first.message;
    for (const Diagnostic& diagnostic : result.diagnostics) EXPECT_NE(diagnostic.message, "no axiom");
}

INSTANTIATE_TEST_SUITE_P(
    Crankshaw, DialectErrors,
    ::testing::Values(
        ErrorCase{Dialect::Crankshaw, "#n 6;", 1, 4, "unexpected '6'"},
        ErrorCase{Dialect::Crankshaw, "#w : A;\n#w : A(1;", 2, 9, "malformed parameter list"},
        ErrorCase{Dialect::Crankshaw, "#w : A;\n\n#p1 : A : * B;", 3, 13, "unexpected 'B'"},
        ErrorCase{Dialect::Crankshaw, "#w : A; #p1 : A B : * : C;", 1, 19, "a predecessor is one module"},
        ErrorCase{Dialect::Crankshaw, "#define : 5;", 1, 9, "missing constant name"},
        ErrorCase{Dialect::Crankshaw, "#w : A; x", 1, 9, "unexpected 'x'"},
        ErrorCase{Dialect::Crankshaw, "#w : A;\n#p1 : A(x+1) : * : B;", 2, 10, "malformed parameter list"},
        ErrorCase{Dialect::Crankshaw, "#w : {1,2};", 1, 6, "unexpected '{'"},
        ErrorCase{Dialect::Crankshaw, "#define r {1, 2;", 1, 16, "unclosed random range"},
        ErrorCase{Dialect::Crankshaw, "#foo", 1, 5, "statement ends early"},
        ErrorCase{Dialect::Crankshaw, "#w : A; #define a 1; /* unclosed", 1, 22, "comment"},
        // Found by the native parser in the translation, moved back to the dialect text:
        ErrorCase{Dialect::Crankshaw, "#q : A : ~0.5 : B;\n#w : A;", 1, 6, "sum to 0.5"},
        ErrorCase{Dialect::Crankshaw, "#n = 2; #define a 1;\n#w : A(a);\n#p1 : A(x) : * : B(x +);", 3, 23,
                  "unexpected ')'"},
        ErrorCase{Dialect::Crankshaw, "#w : ab;\n#p1 : ab : * : ab(q);", 2, 19, "q"},
        ErrorCase{Dialect::Crankshaw, "#n = 2;\n#w : A;\n\n  #p1 : A : x > 1 : B;", 4, 13, "unknown name 'x'"}));

INSTANTIATE_TEST_SUITE_P(
    Robbins, DialectErrors,
    ::testing::Values(ErrorCase{Dialect::Robbins, "X\nA --> B ,", 2, 9, "unknown symbol ','"},
                      ErrorCase{Dialect::Robbins, "iterations x", 1, 12, "missing value of 'iterations'"},
                      ErrorCase{Dialect::Robbins, "X\nA --> |(2)", 2, 8, "'|' takes no value"},
                      ErrorCase{Dialect::Robbins, "X\nA --> F(1", 2, 8, "unclosed '('"},
                      ErrorCase{Dialect::Robbins, "angle 30 X X --> @", 1, 18, "unknown symbol '@'"},
                      ErrorCase{Dialect::Robbins, "X\n\nA --> F(1 +)", 3, 12, "unexpected ')'"},
                      ErrorCase{Dialect::Robbins, "A\nA -->  --> B", 2, 8, "production"}));

INSTANTIATE_TEST_SUITE_P(
    Plantlang, DialectErrors,
    ::testing::Values(ErrorCase{Dialect::Plantlang, "Axiom = dQ2", 1, 11, "'Q' takes no value"},
                      ErrorCase{Dialect::Plantlang, "Axiom = d<(2)", 1, 11, "unknown command '('"},
                      ErrorCase{Dialect::Plantlang, "Axiom = +5", 1, 10, "'+' takes no value"},
                      ErrorCase{Dialect::Plantlang, "Axiom = X\n  Foo = 3", 2, 3, "unknown setting 'foo'"},
                      ErrorCase{Dialect::Plantlang, "Default angle = abc", 1, 17, "not a number"},
                      ErrorCase{Dialect::Plantlang, "Axiom = X\n(0.2 X => d", 2, 6, "malformed probability"},
                      ErrorCase{Dialect::Plantlang, "Axiom = X\nd(3) => X", 2, 1, "without a value"},
                      ErrorCase{Dialect::Plantlang, "Axiom = X\nX = > d", 2, 1, "unknown setting"},
                      ErrorCase{Dialect::Plantlang, "hello", 1, 1, "unrecognised line"},
                      ErrorCase{Dialect::Plantlang, "Axiom = d(-)", 1, 11, "malformed value"},
                      ErrorCase{Dialect::Plantlang, "Axiom = X\n(0.3) X => d", 2, 7, "sum to 0.3"},
                      ErrorCase{Dialect::Plantlang, "Axiom = d\nX => d#X\nwhat", 2, 7, "'#'"}));

// Every prefix of every data file, and random corruptions of them, in every
// dialect: the translators and the parser must return, whatever the input.
TEST(DialectRobustness, TruncatedAndCorruptedFilesNeverCrash) {
    const char* files[] = {"plants/dialects/tree_7_1.crankshaw",
                           "plants/dialects/gravity_tree_2d.crankshaw",
                           "plants/dialects/robbins_first_example.robbins",
                           "plants/dialects/robbins_sample_a.robbins",
                           "plants/dialects/fig38_tree.plantlang",
                           "plants/dialects/stochastic_bush.plantlang"};
    const char alphabet[] = "#;:~{}(),<>-=+[]!'\"?$%|. \n\tAFXab01\x80\xff";
    std::mt19937 random(1);
    size_t inputs = 0;
    for (const char* file : files) {
        std::string problem;
        std::string text = readTextFile(dataPath(file), problem);
        ASSERT_EQ(problem, "") << file;
        for (size_t length = 0; length <= text.size(); length += 3) {
            std::string input = text.substr(0, length);
            if (!input.empty() && length % 2 == 0)
                input[random() % input.size()] = alphabet[random() % (sizeof alphabet - 1)];
            for (Dialect dialect : {Dialect::Crankshaw, Dialect::Robbins, Dialect::Plantlang}) {
                ParseResult result = parseDialect(dialect, input);
                for (const Diagnostic& diagnostic : result.diagnostics) EXPECT_GE(diagnostic.line, 1) << input;
                ++inputs;
            }
        }
    }
    EXPECT_GT(inputs, 1000u);
}

// Recovery after an error must not rescan long words (this would take hours if quadratic).
TEST(DialectRobustness, LongInputsAfterAnErrorTakeLinearTime) {
    std::string word(300000, 'a');
    std::string spaces(300000, ' ');
    ParseResult robbins = parseDialect(Dialect::Robbins, "X\nA --> , " + word + spaces + word + "\nB --> C");
    ASSERT_FALSE(robbins.diagnostics.empty());
    EXPECT_EQ(robbins.diagnostics.front().line, 2);
    ParseResult crankshaw = parseDialect(Dialect::Crankshaw, "#w : A; ," + word + spaces + ";");
    ASSERT_FALSE(crankshaw.diagnostics.empty());
    ParseResult plantlang = parseDialect(Dialect::Plantlang, "Axiom = " + std::string(300000, 'd') + "?");
    ASSERT_FALSE(plantlang.diagnostics.empty());
    EXPECT_EQ(plantlang.diagnostics.front().column, 300009);
}

TEST(DialectRobustness, DeeplyNestedRangesAreAnErrorNotAStackOverflow) {
    std::string source = "#define r " + std::string(100000, '{') + "1;\n#w : A;";
    ParseResult result = parseDialect(Dialect::Crankshaw, source);
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_EQ(result.diagnostics.front().line, 1);
    EXPECT_EQ(result.diagnostics.front().column, 27);
    EXPECT_NE(result.diagnostics.front().message.find("nested too deeply"), std::string::npos);
}

} // namespace
} // namespace lsys::test
