#pragma once
// Arithmetic expressions (parameters, conditions, #define values) compiled once
// to a postfix bytecode and evaluated on a fixed-size stack: no allocation at
// evaluation time, which happens once per parameter per rewritten module.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "lsystem/lexer.h"
#include "lsystem/random.h"

namespace lsys {

enum class Op : uint8_t {
    Const,
    Var,
    Neg,
    Not,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Mod,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Select, // c ? a : b, with all three evaluated
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sqrt,
    Exp,
    Log,
    Abs,
    Floor,
    Ceil,
    Min,
    Max,
    Clamp,
    Ran,
    NRan,
};

struct Instruction {
    Op op;
    uint16_t variable = 0; // for Var
    double value = 0;      // for Const
};

inline constexpr int kMaxStack = 32;     // deepest evaluation stack an expression may need
inline constexpr int kMaxNesting = 64;   // parser recursion bound
inline constexpr int kMaxVariables = 64; // formal parameters of one production

struct Expression {
    std::vector<Instruction> code;
    bool isConstant() const { return code.size() == 1 && code[0].op == Op::Const; }
};

// Names an expression may refer to: the production's formal parameters
// (evaluated from a variable array) and the grammar's constants (folded in).
struct ExpressionScope {
    std::span<const std::string> variables;
    const std::unordered_map<std::string, double>* constants = nullptr;
};

// Parses an expression starting at the cursor. Stops before the first
// character that cannot continue it (',' ')' ':' an arrow, end of line).
// On error appends a diagnostic and returns nullopt.
std::optional<Expression> parseExpression(Cursor& cursor, const ExpressionScope& scope, const std::string& file,
                                          std::vector<Diagnostic>& diagnostics);

double evaluate(const Expression& expression, const double* variables, RandomStream& random);

} // namespace lsys
