#pragma once
// Arithmetic expressions (parameters, conditions, #define values) compiled once
// to a postfix bytecode and evaluated on a fixed-size stack: no allocation at
// evaluation time, which happens once per parameter per rewritten module.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "lsystem/common/random.h"
#include "lsystem/language/lexer.h"

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
    // Global variables and arrays (lsystem/language/statements.h): the slot is in value.
    Global,
    Element, // pops a flat index; reads slot value + index when below extent, else 0
    Int,     // truncation toward zero, as C converts an array index
    // cpfg's arithmetic (Arithmetic::Cpfg; Měch 2005, §5.1's expressions).
    SinDegrees,
    CosDegrees,
    TanDegrees,
    AsinDegrees,
    AcosDegrees,
    AtanDegrees,
    Atan2Cpfg, // atan2(a, b) is C's atan2(b, a), in degrees
    DivCpfg,   // a / 0 is a (cpfg warns and divides by 1)
    ModInt,    // (int)a % (int)b; 0 when (int)b is 0
    Sign,
    Round, // cpfg's trunc(x): floor(x + 0.5)
    Srand, // reseeds the random stream with (integer) t; yields 0
    Func,  // cpfg's func(id, x): function (int)id of the expression's table at x; 0 for an id not in it
};

// The functions cpfg's func(id, x) reads, each y(x), in the order the view
// file names them (func(1, x) is the first); shared by every expression that
// calls func. A vlab object's function files make them
// (vlab::functionTable, lsystem/vlab/function_file.h).
using FunctionTable = std::shared_ptr<const std::vector<std::function<double(double)>>>;

struct Instruction {
    Op op;
    uint16_t variable = 0; // for Var
    uint32_t extent = 0;   // for Element: the array's size
    double value = 0;      // for Const; the slot for Global and Element
};

inline constexpr int kMaxStack = 32;     // deepest evaluation stack an expression may need
inline constexpr int kMaxNesting = 64;   // parser recursion bound
inline constexpr int kMaxVariables = 64; // formal parameters of one production

struct Expression {
    std::vector<Instruction> code;
    FunctionTable functions; // set when the code calls func, which evaluate() then reads
    bool isConstant() const { return code.size() == 1 && code[0].op == Op::Const; }
};

// A grammar's global variables (cpfg's, set by statement blocks) and arrays:
// slots of one array of doubles that a derivation carries from step to step.
struct GlobalVariable {
    std::string name;
    uint32_t slot = 0;
    std::vector<uint32_t> extents; // empty for a scalar; an array's dimensions otherwise
    uint32_t size() const;
};

struct GlobalTable {
    std::vector<GlobalVariable> variables;
    std::vector<double> initial; // one per slot: 0, or an array's initialiser
    const GlobalVariable* find(std::string_view name) const;
    // Adds a variable (all zeros); nullptr when the slots would pass kMaxGlobalSlots.
    const GlobalVariable* add(std::string name, std::vector<uint32_t> extents = {});
};
inline constexpr uint32_t kMaxGlobalSlots = 1u << 24;

// How functions and operators compute: natively (radians, IEEE division), or
// as cpfg does: trigonometric functions in degrees, cpfg's atan2 argument
// order, x/0 = x, '%' on integers, trunc() rounding, sign(), srand().
enum class Arithmetic : uint8_t { Native, Cpfg };

// Names an expression may refer to: the production's formal parameters and
// local variables (evaluated from a variable array), the grammar's global
// variables (from the derivation's global array) and its constants (folded in).
struct ExpressionScope {
    std::span<const std::string> variables;
    const std::unordered_map<std::string, double>* constants = nullptr;
    const GlobalTable* globals = nullptr;
    Arithmetic arithmetic = Arithmetic::Native;
    FunctionTable functions; // func(id, x) is known only with a non-empty table
};

// Parses an expression starting at the cursor. Stops before the first
// character that cannot continue it (',' ')' ':' an arrow, end of line).
// On error appends a diagnostic and returns nullopt.
std::optional<Expression> parseExpression(Cursor& cursor, const ExpressionScope& scope, const std::string& file,
                                          std::vector<Diagnostic>& diagnostics);

// `globals` is the derivation's global array; only grammars with global
// variables have expressions that read it.
double evaluate(const Expression& expression, const double* variables, RandomStream& random,
                const double* globals = nullptr);

// Whether the expression has an effect beyond its value (srand): such
// grammars are derived sequentially (lsystem/rewriting/rewriter.h).
bool hasSideEffects(const Expression& expression);

} // namespace lsys
