// Expressions: parsing, precedence, functions, random draws and errors.

#include <cmath>
#include <numbers>

#include "lsystem/vlab/function_file.h"
#include "test_support.h"

namespace lsys::test {
namespace {

struct Evaluated {
    std::optional<double> value;
    std::vector<Diagnostic> diagnostics;
    size_t stoppedAt = 0;
};

Evaluated evaluateText(std::string_view text, std::vector<std::string> variables = {}, const double* values = nullptr,
                       uint64_t seed = 0) {
    std::unordered_map<std::string, double> constants{{"k", 3.0}};
    Evaluated result;
    Cursor cursor{text, 0, 1};
    std::optional<Expression> expression =
        parseExpression(cursor, ExpressionScope{variables, &constants}, "test", result.diagnostics);
    result.stoppedAt = cursor.pos;
    if (expression) {
        RandomStream random = RandomStream::forModule(seed, 1, 0);
        result.value = evaluate(*expression, values, random);
    }
    return result;
}

double value(std::string_view text) {
    Evaluated result = evaluateText(text);
    EXPECT_TRUE(result.value.has_value())
        << text << ": " << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
    return result.value.value_or(NAN);
}

TEST(LsysExpression, ArithmeticAndPrecedence) {
    EXPECT_DOUBLE_EQ(value("2+3*4"), 14);
    EXPECT_DOUBLE_EQ(value("(2+3)*4"), 20);
    EXPECT_DOUBLE_EQ(value("10-4-3"), 3);
    EXPECT_DOUBLE_EQ(value("2^3^2"), 512);
    EXPECT_DOUBLE_EQ(value("-2^2"), -4);
    EXPECT_DOUBLE_EQ(value("2^-1"), 0.5);
    EXPECT_DOUBLE_EQ(value("7%3"), 1);
    EXPECT_DOUBLE_EQ(value("1/4"), 0.25);
    EXPECT_DOUBLE_EQ(value(".5e1 + 1e-1"), 5.1);
    EXPECT_DOUBLE_EQ(value("k*2"), 6);
}

TEST(LsysExpression, ComparisonsAndLogic) {
    EXPECT_EQ(value("1<2"), 1);
    EXPECT_EQ(value("2<=1"), 0);
    EXPECT_EQ(value("3>=3 && 2!=2"), 0);
    EXPECT_EQ(value("0 || 1 == 1"), 1);
    EXPECT_EQ(value("!0"), 1);
    EXPECT_EQ(value("!(2>1)"), 0);
    EXPECT_EQ(value("1 + 1 == 2"), 1); // comparison binds looser than arithmetic
}

TEST(LsysExpression, Conditional) {
    EXPECT_EQ(value("1 ? 2 : 3"), 2);
    EXPECT_EQ(value("0 ? 2 : 3"), 3);
    EXPECT_EQ(value("0 ? 1 : 0 ? 2 : 4"), 4);
}

TEST(LsysExpression, Functions) {
    EXPECT_NEAR(value("sin(3.14159265358979/2)"), 1, 1e-12);
    EXPECT_NEAR(value("cos(0) + tan(0)"), 1, 1e-12);
    EXPECT_NEAR(value("asin(1)*2"), std::numbers::pi, 1e-12);
    EXPECT_NEAR(value("acos(-1)"), std::numbers::pi, 1e-12);
    EXPECT_NEAR(value("atan(1)*4"), std::numbers::pi, 1e-12);
    EXPECT_NEAR(value("atan2(1, 0)"), std::numbers::pi / 2, 1e-12);
    EXPECT_DOUBLE_EQ(value("sqrt(16) + exp(0) + log(1)"), 5);
    EXPECT_DOUBLE_EQ(value("abs(-2.5)"), 2.5);
    EXPECT_DOUBLE_EQ(value("floor(-1.5) + ceil(1.2)"), 0);
    EXPECT_DOUBLE_EQ(value("min(3, 4) + max(3, 4)"), 7);
    EXPECT_DOUBLE_EQ(value("clamp(5, 0, 2) + clamp(-1, 0, 2) + clamp(1, 0, 2)"), 3);
}

TEST(LsysExpression, Variables) {
    const double values[] = {2.0, 5.0};
    Evaluated result = evaluateText("x*10 + y", {"x", "y"}, values);
    EXPECT_EQ(result.value, 25.0);
    // A parameter shadows a constant of the same name.
    const double shadow[] = {10.0};
    EXPECT_EQ(evaluateText("k", {"k"}, shadow).value, 10.0);
}

TEST(LsysExpression, StopsBeforeWhatCannotContinueIt) {
    const double x[] = {1.0};
    EXPECT_EQ(evaluateText("1+2, 3").stoppedAt, 3u);
    EXPECT_EQ(evaluateText("x > 0 --> F", {"x"}, x).stoppedAt, 6u);
    EXPECT_EQ(evaluateText("x > 0 -> F", {"x"}, x).stoppedAt, 6u);
    EXPECT_EQ(evaluateText("2) : 0.5").stoppedAt, 1u);
}

TEST(LsysExpression, RanIsUniformInRange) {
    double sum = 0;
    for (uint64_t seed = 0; seed < 4000; ++seed) {
        double v = *evaluateText("ran(2)", {}, nullptr, seed).value;
        ASSERT_GE(v, 0.0);
        ASSERT_LT(v, 2.0);
        sum += v;
    }
    EXPECT_NEAR(sum / 4000, 1.0, 0.05);
}

TEST(LsysExpression, NranHasTheRequestedMeanAndSpread) {
    double sum = 0, squares = 0;
    const int n = 4000;
    for (int seed = 0; seed < n; ++seed) {
        double v = *evaluateText("nran(10, 2)", {}, nullptr, static_cast<uint64_t>(seed)).value;
        sum += v;
        squares += v * v;
    }
    const double mean = sum / n;
    EXPECT_NEAR(mean, 10.0, 0.15);
    EXPECT_NEAR(std::sqrt(squares / n - mean * mean), 2.0, 0.15);
}

TEST(LsysExpression, SuccessiveDrawsDiffer) {
    Evaluated result = evaluateText("ran(1) - ran(1)");
    ASSERT_TRUE(result.value);
    EXPECT_NE(*result.value, 0.0);
}

TEST(LsysExpression, ConstantsAreFolded) {
    std::vector<Diagnostic> diagnostics;
    std::unordered_map<std::string, double> constants{{"k", 3.0}};
    Cursor cursor{"k*2 + sin(0)", 0, 1};
    std::optional<Expression> expression = parseExpression(cursor, ExpressionScope{{}, &constants}, "t", diagnostics);
    ASSERT_TRUE(expression);
    EXPECT_TRUE(expression->isConstant());
}

struct BadExpression {
    const char* text;
    int column;
    const char* message;
};

TEST(LsysExpression, Errors) {
    const BadExpression cases[] = {
        {"1 +", 4, "expression ends too early"}, {"(1 + 2", 7, "unbalanced parenthesis"},
        {"foo + 1", 1, "unknown name 'foo'"},    {"sin 1", 5, "needs arguments"},
        {"min(1)", 6, "takes 2 arguments"},      {"1 ? 2", 6, "incomplete conditional"},
        {"1..2", 1, "malformed number"},         {"* 2", 1, "unexpected '*'"},
    };
    for (const BadExpression& c : cases) {
        Evaluated result = evaluateText(c.text);
        EXPECT_FALSE(result.value) << c.text;
        ASSERT_EQ(result.diagnostics.size(), 1u) << c.text;
        EXPECT_EQ(result.diagnostics[0].column, c.column) << c.text;
        EXPECT_NE(result.diagnostics[0].message.find(c.message), std::string::npos)
            << c.text << ": " << result.diagnostics[0].message;
    }
}

TEST(LsysExpression, DeepNestingIsAnErrorNotACrash) {
    std::string deep(100000, '(');
    Evaluated result = evaluateText(deep + "1");
    EXPECT_FALSE(result.value);
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_NE(result.diagnostics[0].message.find("nested too deeply"), std::string::npos);
    std::string minus(100000, '-');
    EXPECT_FALSE(evaluateText(minus + "1").value);
}

TEST(LsysExpression, LongFlatExpressionStaysWithinTheStack) {
    std::string sum = "1";
    for (int i = 0; i < 1000; ++i) sum += "+1";
    EXPECT_EQ(evaluateText(sum).value, 1001.0);
    // Right-nested sums need one stack slot per level: past kMaxStack it is an error, never an overflow.
    std::string rightHeavy = "x";
    for (int i = 0; i < kMaxStack + 5; ++i) rightHeavy = "x+(" + rightHeavy + ")";
    Evaluated result = evaluateText(rightHeavy, {"x"});
    EXPECT_FALSE(result.value);
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_NE(result.diagnostics[0].message.find("too complex"), std::string::npos);
}

// cpfg's func(id, x) reads a table of the object's function files
// (vlab::functionTable). These functions are given by their samples:
// func(1, x) interpolates 0, 0.5, 2 and func(2, x) is 3 throughout.
FunctionTable twoFunctions() {
    vlab::VlabFunction rising, flat;
    rising.samples = {0.0, 0.5, 2.0};
    flat.samples = {3.0, 3.0};
    return vlab::functionTable({rising, flat});
}

std::optional<double> withFunctions(std::string_view text, std::vector<Diagnostic>& diagnostics, double x = 0) {
    const std::vector<std::string> variables{"x", "i"};
    const std::unordered_map<std::string, double> constants{{"FLAT", 2.0}};
    Cursor cursor{text, 0, 3};
    const std::optional<Expression> expression =
        parseExpression(cursor, ExpressionScope{variables, &constants, nullptr, Arithmetic::Cpfg, twoFunctions()},
                        "plant.l", diagnostics);
    if (!expression) return std::nullopt;
    RandomStream random;
    const double values[] = {x, 1.9};
    return evaluate(*expression, values, random);
}

TEST(LsysExpression, FuncReadsTheFunctionTable) {
    std::vector<Diagnostic> diagnostics;
    EXPECT_DOUBLE_EQ(withFunctions("func(1, x)", diagnostics, 0.75).value_or(NAN), 1.25);
    EXPECT_DOUBLE_EQ(withFunctions("func(1, x)", diagnostics, 7).value_or(NAN), 2.0); // x is clamped to [0, 1]
    EXPECT_DOUBLE_EQ(withFunctions("func(FLAT, 0.2) + func(i, 0.25)", diagnostics).value_or(NAN), 3.25);
    // A computed id is converted to int, as cpfg converts it; one outside the table gives 0.
    EXPECT_DOUBLE_EQ(withFunctions("func(i + 1, x)", diagnostics).value_or(NAN), 3.0);
    EXPECT_DOUBLE_EQ(withFunctions("func(i * 2, x)", diagnostics).value_or(NAN), 0.0);
    EXPECT_TRUE(diagnostics.empty()) << diagnostics[0].message;
}

TEST(LsysExpression, FuncOfConstantsIsFolded) {
    std::vector<Diagnostic> diagnostics;
    const std::unordered_map<std::string, double> constants;
    Cursor cursor{"func(1, 0.5) * 2", 0, 1};
    const std::optional<Expression> expression = parseExpression(
        cursor, ExpressionScope{{}, &constants, nullptr, Arithmetic::Cpfg, twoFunctions()}, "t", diagnostics);
    ASSERT_TRUE(expression);
    ASSERT_TRUE(expression->isConstant());
    EXPECT_DOUBLE_EQ(expression->code[0].value, 1.0);
}

TEST(LsysExpression, FuncNamesAFunctionThatExists) {
    const std::pair<const char*, int> cases[] = {{"func(3, x)", 6}, {"func( 0.5, x)", 7}, {"func(FLAT + 1, x)", 6}};
    for (const auto& [text, column] : cases) {
        std::vector<Diagnostic> diagnostics;
        EXPECT_FALSE(withFunctions(text, diagnostics)) << text;
        ASSERT_EQ(diagnostics.size(), 1u) << text;
        EXPECT_EQ(diagnostics[0].file, "plant.l");
        EXPECT_EQ(diagnostics[0].line, 3);
        EXPECT_EQ(diagnostics[0].column, column) << text;
        EXPECT_NE(diagnostics[0].message.find("the object's view file names 2 functions"), std::string::npos)
            << diagnostics[0].message;
        EXPECT_EQ(diagnostics[0].expected, "an id from 1 to 2");
    }
}

TEST(LsysExpression, FuncWithoutFunctionFilesIsAnError) {
    Evaluated result = evaluateText("2 * func(1, 0.5)");
    EXPECT_FALSE(result.value);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].column, 5);
    EXPECT_NE(result.diagnostics[0].message.find("no function files are given"), std::string::npos);
}

} // namespace
} // namespace lsys::test
