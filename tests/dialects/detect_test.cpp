// Choosing the dialect: names and the header line.

#include "dialect_test_support.h"

namespace lsys::dialects::test {
namespace {

TEST(DialectNames, KnownNamesInAnyCase) {
    EXPECT_EQ(dialectFromName("crankshaw"), Dialect::Crankshaw);
    EXPECT_EQ(dialectFromName("Robbins"), Dialect::Robbins);
    EXPECT_EQ(dialectFromName("PLANTLANG"), Dialect::Plantlang);
    EXPECT_EQ(dialectFromName("native"), Dialect::Native);
    EXPECT_EQ(dialectFromName("cpfg"), std::nullopt);
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
    EXPECT_EQ(detectDialect("Axiom: F\ndialect: robbins\n"), Dialect::Native);  // not the first line
    EXPECT_EQ(detectDialect("dialect: klingon\n"), Dialect::Native);
    EXPECT_EQ(detectDialect("dialect: robbins extra\n"), Dialect::Native);
}

TEST(DetectDialect, NativeFileWithHeaderParses) {
    Grammar grammar = parseOk(Dialect::Native, "dialect: native\nAxiom: F\nF --> FF\n");
    EXPECT_EQ(deriveSteps(grammar, 2).size(), 4u);
}

}  // namespace
}  // namespace lsys::dialects::test
