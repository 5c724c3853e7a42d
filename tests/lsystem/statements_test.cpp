// cpfg's statement blocks and global variables (lsystem/language/statements.h):
// blocks around a production's condition, Start:/StartEach:/EndEach:/End:,
// define: arrays, sequential rewriting in string order, cpfg's arithmetic,
// and the errors of malformed blocks.

#include "test_support.h"

namespace lsys::test {
namespace {

std::string firstError(const std::string& source) {
    ParseResult result = parseLsystem(source);
    return result.diagnostics.empty() ? std::string() : formatDiagnostic(result.diagnostics[0], source);
}

TEST(Statements, GlobalBlocksRunAtTheStartAndAroundEachStep) {
    const std::string source = "Start: {n = 10; steps = 0;}\n"
                               "StartEach: {steps = steps + 1;}\n"
                               "EndEach: {n = n * 2;}\n"
                               "Axiom: A(n)\n" // evaluated after Start:
                               "A(x) --> B(x, steps, n) A(x)\n";
    EXPECT_EQ(derived(source, 3), "B(10,1,10)B(10,2,20)B(10,3,40)A(10)");
}

TEST(Statements, BlocksBeforeAndAfterTheConditionUseLocals) {
    const std::string source = "Axiom: A(1) A(2) A(3)\n"
                               "A(x) : {y = x * 2;} y > 2 {z = y + 1;} --> B(y, z)\n";
    EXPECT_EQ(derived(source, 1), "A(1)B(4,5)B(6,7)");
    // A block after the condition runs only when it holds; the one before runs on every match.
    const std::string counting = "Start: {tried = 0; applied = 0;}\n"
                                 "Axiom: A(1) A(2) A(3) C\n"
                                 "A(x) : {tried = tried + 1;} x > 1 {applied = applied + 1;} --> B\n"
                                 "C --> C(tried, applied)\n";
    EXPECT_EQ(derived(counting, 1), "A(1)BBC(3,2)");
}

TEST(Statements, RewritingIsSequentialInStringOrder) {
    Grammar grammar = parseOk("Start: {n = 0;}\nAxiom: A A A A A A\nA : {n = n + 1;} * --> B(n)\n");
    EXPECT_TRUE(grammar.sequential);
    DeriveOptions options = stepsOf(1);
    options.threads = 4;
    options.parallelThreshold = 1; // would split the string if the grammar allowed it
    EXPECT_EQ(toString(derive(grammar, options), grammar.symbols), "B(1)B(2)B(3)B(4)B(5)B(6)");
    EXPECT_FALSE(parseOk("Axiom: A\nA --> B\n").sequential);
}

TEST(Statements, IfElseWhileAndDo) {
    const std::string source = "Axiom: A(5)\n"
                               "A(x) : {s = 0; i = 0; while (i < x) {i = i + 1; s = s + i;} "
                               "if (s > 10) {big = 1;} else {big = 0;} "
                               "d = 0; do {d = d + 1;} while (d < 0);} * --> B(s, big, d)\n";
    EXPECT_EQ(derived(source, 1), "B(15,1,1)");
}

// A local keeps its value from one application of its production to the
// next, across modules and steps, as in cpfg (each production has its own
// symbol table, lsys_input.y); each production has its own, and a block
// before a condition that fails still keeps what it assigned.
TEST(Statements, LocalsKeepTheirValueFromOneApplicationToTheNext) {
    EXPECT_EQ(derived("Axiom: A A\nA : {k = k + 1;} * --> B(k) A\n", 2), "B(1)B(3)AB(2)B(4)A");
    EXPECT_EQ(derived("Axiom: A C A C\nA : {k = k + 1;} * --> B(k)\nC : {k = k + 10;} * --> D(k)\n", 1),
              "B(1)D(10)B(2)D(20)");
    EXPECT_EQ(derived("Axiom: A(1) A(0) A(5) A(3)\nA(x) : {seen = seen + 1;} x > 2 {last = x;} --> B(seen, last)\n", 1),
              "A(1)A(0)B(3,5)B(4,3)");
    // Each derivation starts them at 0 again.
    const Grammar grammar = parseOk("Axiom: A\nA : {k = k + 1;} * --> B(k)\n");
    EXPECT_EQ(toString(derive(grammar, stepsOf(1)), grammar.symbols), "B(1)");
    EXPECT_EQ(toString(derive(grammar, stepsOf(1)), grammar.symbols), "B(1)");
}

TEST(Statements, DefineArraysAndTheirElements) {
    const std::string source = "define: {array a[2][3] = {1, 2, 3, 4, 5, 6}, b[4];}\n"
                               "Start: {a[0][0] = 7; b[3] = a[1][2] + 0.5;}\n"
                               "Axiom: A\n"
                               "A --> B(a[0][0], a[1][1], b[3], a[5][0], a[1.9][0.9])\n";
    // a[5][0] is outside the array: it reads 0. Indices are truncated, as C converts them.
    EXPECT_EQ(derived(source, 1), "B(7,5,6.5,0,4)");
    EXPECT_NE(firstError("define: {array a[2] = {1, 2, 3};}\nAxiom: A\n").find("more values than 'a' holds"),
              std::string::npos);
    EXPECT_NE(firstError("Start: {array a[2];}\nAxiom: A\n").find("arrays are defined in the 'define:' block"),
              std::string::npos);
    EXPECT_NE(firstError("define: {array a[2];}\nAxiom: A\nA --> B(a)\n").find("'a' is an array"), std::string::npos);
}

TEST(Statements, CpfgArithmetic) {
    const std::string source = "arithmetic: cpfg\n"
                               "Axiom: A\n"
                               "A --> B(sin(90), cos(180), atan2(0, 1), atan(1), 7 / 0, 7 % 3, -7 % 3, trunc(2.5), "
                               "trunc(-2.5), sign(-3), fabs(-2))\n";
    EXPECT_EQ(derived(source, 1), "B(1,-1,90,45,7,1,-1,3,-2,-1,2)");
    // Natively trigonometry is in radians and x/0 is infinite.
    EXPECT_EQ(derived("Axiom: A\nA --> B(sin(0), 1 / 0)\n", 1), "B(0,inf)");
    EXPECT_NE(firstError("arithmetic: fortran\nAxiom: A\n").find("unknown arithmetic"), std::string::npos);
}

TEST(Statements, SrandMakesTheRandomStreamRepeatable) {
    const std::string source = "arithmetic: cpfg\n"
                               "Start: {srand(7);}\n"
                               "Axiom: A A A\n"
                               "A --> B(ran(1))\n";
    Grammar grammar = parseOk(source);
    EXPECT_TRUE(grammar.sequential);
    const std::string once = toString(derive(grammar, stepsOf(1)), grammar.symbols);
    EXPECT_EQ(toString(derive(grammar, stepsOf(1)), grammar.symbols), once);
    DeriveOptions otherSeed = stepsOf(1);
    otherSeed.seed = 99; // srand decides, not the grammar's seed
    EXPECT_EQ(toString(derive(grammar, otherSeed), grammar.symbols), once);
}

TEST(Statements, PrintfWritesToStandardError) {
    Grammar grammar = parseOk("Axiom: A(2) A(3)\n"
                              "A(x) : {printf(\"x=%g %d%% %s\\n\", x, x * 10);} * --> B\n");
    testing::internal::CaptureStderr();
    derive(grammar, stepsOf(1));
    // %s has no string to print: it is written as it is, never read from memory.
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "x=2 20% %s\nx=3 30% %s\n");
}

TEST(Statements, ALoopThatNeverEndsIsAnError) {
    Grammar grammar = parseOk("Start: {x = 1; while (x) {x = 1;}}\nAxiom: A\n");
    EXPECT_THROW(derive(grammar, stepsOf(1)), DerivationError);
}

TEST(Statements, MalformedBlocksAreLocated) {
    EXPECT_NE(firstError("Start: {n = 1;\nAxiom: A\n").find("<input>:1:15: error: statement block not closed"),
              std::string::npos);
    EXPECT_NE(firstError("Axiom: A\nA : {x = ;} * --> B\n").find("<input>:2:10: error: "), std::string::npos);
    EXPECT_NE(firstError("Start: {if x > 1 {y = 1;}}\nAxiom: A\n").find("expected '(' after if"), std::string::npos);
    EXPECT_NE(firstError("Start: {do {y = 1;}}\nAxiom: A\n").find("needs its condition"), std::string::npos);
    EXPECT_NE(
        firstError("Start: {f = fopen(\"x\", \"w\");}\nAxiom: A\n").find("cpfg's function 'fopen' is not supported"),
        std::string::npos);
    EXPECT_NE(firstError("Start: {n = 1}\nAxiom: A\n").find("expected ';' after the assignment"), std::string::npos);
    EXPECT_NE(firstError("Start: {n[2] = 1;}\nAxiom: A\n").find("'n' is not an array"), std::string::npos);
}

} // namespace
} // namespace lsys::test
