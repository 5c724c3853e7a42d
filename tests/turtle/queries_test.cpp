// cpfg's query modules (lsystem/rewriting/queries.h): before each step the turtle
// writes its position, heading, left or up vector into the module after '?'.

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include "lsystem/language/parser.h"
#include "lsystem/rewriting/rewriter.h"

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

// cpfg's turtle draws as ours but calls -U its up vector (L x H, starting at
// (0,0,-1)): a cpfg file's ?U answers that one; ?H and ?L are the same.
TEST(QueryModules, ACpfgFilesUpIsLCrossH) {
    Grammar grammar = parsed("turtle modules: cpfg\nangle: 90\nAxiom: &?H(0,0,0)?L(0,0,0)?U(0,0,0)\nB --> B\n");
    const ModuleString string = deriveText(grammar, 0);
    auto expectAt = [&](size_t module, glm::vec3 expected) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(string.parameters(module)[k], expected[k], 1e-6f) << module << " " << k;
    };
    // & pitched H from +Y down to -Z; L stays -X; H x L is +Y, L x H is -Y.
    expectAt(2, {0, 0, -1});
    expectAt(4, {-1, 0, 0});
    expectAt(6, {0, -1, 0});
}

// cpfg's turtle reads the string through the homomorphism, module by module,
// and a '?' reads its queried module from the string itself (interpret.c,
// InterpretHomomorphism): the answers see what the interpretation rules draw.
TEST(QueryModules, TheTurtleReadsTheStringThroughTheInterpretationRules) {
    Grammar grammar = parsed("Axiom: F(1)?P(0,0,0)I?P(0,0,0)[%F?P(0,0,0)]?U(0,0,0)\nB --> B\n"
                             "interpretation:\nmaximum depth: 2\nF(l) --> F(l)F(l)\nI --> F(1)?P(0,0,0)-\n"
                             "U(a,b,c) --> F\n");
    const ModuleString string = deriveText(grammar, 0);
    auto expectAt = [&](size_t module, glm::vec3 expected) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(string.parameters(module)[k], expected[k], 1e-6f) << module << " " << k;
    };
    // F(1) ? P I ? P [ % F ? P ] ? U: F(1) is four segments (two levels), I
    // two and a turn (its own ?P keeps no answer), the cut ?P is not answered
    // and U is not rewritten after its '?'.
    ASSERT_EQ(string.size(), 14u);
    expectAt(2, {0, 4, 0});
    expectAt(5, {0, 6, 0});
    expectAt(10, {0, 0, 0});
    expectAt(13, {0, 0, 1});
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
