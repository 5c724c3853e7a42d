// Choosing the dialect: names and the header line.

#include "dialect_test_support.h"

namespace lsys::test {
namespace {

TEST(DialectNames, KnownNamesInAnyCase) {
    EXPECT_EQ(dialectFromName("crankshaw"), Dialect::Crankshaw);
    EXPECT_EQ(dialectFromName("Robbins"), Dialect::Robbins);
    EXPECT_EQ(dialectFromName("PLANTLANG"), Dialect::Plantlang);
    EXPECT_EQ(dialectFromName("native"), Dialect::Native);
    EXPECT_EQ(dialectFromName("Cpfg"), Dialect::Cpfg);
    EXPECT_EQ(dialectFromName("lpfg"), std::nullopt);
    EXPECT_EQ(dialectFromName(""), std::nullopt);
    EXPECT_STREQ(dialectName(Dialect::Robbins), "robbins");
}

TEST(DetectDialect, HeaderLineForms) {
    EXPECT_EQ(detectDialect("dialect: crankshaw\n#n = 2;\n"), Dialect::Crankshaw);
    EXPECT_EQ(detectDialect("// dialect: robbins\nFP A\n"), Dialect::Robbins);
    EXPECT_EQ(detectDialect("/* dialect: plantlang */\nAxiom = d\n"), Dialect::Plantlang);
    EXPECT_EQ(detectDialect("# dialect: crankshaw\n"), Dialect::Crankshaw);
    EXPECT_EQ(detectDialect("\n\n   Dialect :  Robbins  \r\nFP A"), Dialect::Robbins);
}

TEST(DetectDialect, NativeWithoutAHeaderOnTheFirstNonBlankLine) {
    EXPECT_EQ(detectDialect(""), Dialect::Native);
    EXPECT_EQ(detectDialect("Axiom: F\nF --> FF\n"), Dialect::Native);
    EXPECT_EQ(detectDialect("Axiom: F\ndialect: robbins\n"), Dialect::Native); // not the first line
    EXPECT_EQ(detectDialect("dialect: klingon\n"), Dialect::Native);
    EXPECT_EQ(detectDialect("dialect: robbins extra\n"), Dialect::Native);
}

// parseDialect without a dialect: what lsys and loadDialectFile do with a file.
TEST(DetectDialect, TheHeaderLineSelectsTheTranslator) {
    EXPECT_TRUE(parseDialect(std::nullopt, "\n// dialect: crankshaw\n#w : A;\n").ok());
    EXPECT_FALSE(parseDialect(std::nullopt, "#w : A;\n").ok());      // native without a header: '#w' is no directive
    EXPECT_TRUE(parseDialect(Dialect::Crankshaw, "#w : A;\n").ok()); // a given dialect needs no header
}

TEST(DetectDialect, UnknownOrMisplacedHeaderIsAnError) {
    for (const char* source : {"dialect: klingon\nAxiom: A\n", "Axiom: A\ndialect: crankshaw\n"}) {
        ParseResult result = parseDialect(std::nullopt, source, {"h.lsys"});
        ASSERT_EQ(result.diagnostics.size(), 1u) << source;
        EXPECT_EQ(result.diagnostics[0].column, 1);
        EXPECT_NE(result.diagnostics[0].message.find("unknown or misplaced dialect line"), std::string::npos);
        EXPECT_NE(result.diagnostics[0].expected.find(knownDialects()), std::string::npos);
    }
}

TEST(DetectDialect, NativeFileWithHeaderParses) {
    Grammar grammar = parseOk(Dialect::Native, "dialect: native\nAxiom: F\nF --> FF\n");
    EXPECT_EQ(deriveSteps(grammar, 2).size(), 4u);
}

} // namespace
} // namespace lsys::test
