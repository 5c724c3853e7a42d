// cpfg's query modules (lsystem/queries.h): before each step the turtle
// writes its position, heading, left or up vector into the module after '?'.

#include <gtest/gtest.h>

#include "lsystem/parser.h"
#include "lsystem/rewriter.h"

namespace lsys {
namespace {

ModuleString deriveText(const Grammar& grammar, int steps) {
    DeriveOptions options;
    options.steps = steps;
    return derive(grammar, options);
}

Grammar parsed(const std::string& source) {
    ParseResult result = parseLsystem(source);
    EXPECT_TRUE(result.ok()) << formatDiagnostics(result.diagnostics, source);
    return std::move(result.grammar);
}

TEST(QueryModules, TheTurtleAnswersPositionHeadingLeftAndUp) {
    Grammar grammar =
        parsed("angle: 90\nAxiom: F(2)?P(0,0,0)+F(1)?P(0,0,0)?H(0,0,0)?L(0,0,0)?U(0,0,0)?P(7)\nB --> B\n");
    EXPECT_TRUE(grammar.queries);
    const ModuleString string = deriveText(grammar, 1);
    auto expectAt = [&](size_t module, std::vector<float> expected) {
        ASSERT_EQ(string.paramCount(module), expected.size()) << module;
        for (size_t k = 0; k < expected.size(); ++k)
            EXPECT_NEAR(string.parameters(module)[k], expected[k], 1e-6f) << module << " " << k;
    };
    // F(2) ? P + F(1) ? P ? H ? L ? U ? P
    expectAt(2, {0, 2, 0});
    expectAt(6, {-1, 2, 0});  // '+' turned the heading from +Y to -X
    expectAt(8, {-1, 0, 0});  // heading
    expectAt(10, {0, -1, 0}); // left
    expectAt(12, {0, 0, 1});  // up
    expectAt(14, {-1});       // fewer parameters take the first coordinates
    EXPECT_FALSE(parsed("Axiom: F?X(0)\n").queries);
}

// The answers come before each step, so conditions and contexts read where
// the turtle stood in the string the step rewrites, and after the last.
TEST(QueryModules, ProductionsReadTheAnswers) {
    Grammar grammar = parsed("Axiom: F(1)A?P(0,0,0)\n"
                             "A > ?P(x,y,z) : y >= 3 --> X\n"
                             "A --> F(1)A\n");
    EXPECT_EQ(toString(deriveText(grammar, 0), grammar.symbols), "F(1)A?P(0,1,0)");
    EXPECT_EQ(toString(deriveText(grammar, 2), grammar.symbols), "F(1)F(1)F(1)A?P(0,3,0)");
    EXPECT_EQ(toString(deriveText(grammar, 3), grammar.symbols), "F(1)F(1)F(1)X?P(0,3,0)");
}

} // namespace
} // namespace lsys
