#include "lsystem/language/expression.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace lsys {

namespace {

struct Function {
    std::string_view name;
    Op op;
    int arity;
};

constexpr Function kFunctions[] = {
    {"sin", Op::Sin, 1},   {"cos", Op::Cos, 1},   {"tan", Op::Tan, 1},     {"asin", Op::Asin, 1},
    {"acos", Op::Acos, 1}, {"atan", Op::Atan, 1}, {"atan2", Op::Atan2, 2}, {"sqrt", Op::Sqrt, 1},
    {"exp", Op::Exp, 1},   {"log", Op::Log, 1},   {"abs", Op::Abs, 1},     {"floor", Op::Floor, 1},
    {"ceil", Op::Ceil, 1}, {"min", Op::Min, 2},   {"max", Op::Max, 2},     {"clamp", Op::Clamp, 3},
    {"ran", Op::Ran, 1},   {"nran", Op::NRan, 2},
};

// cpfg's functions where they differ from the native ones (the rest are shared).
constexpr Function kCpfgFunctions[] = {
    {"sin", Op::SinDegrees, 1},   {"cos", Op::CosDegrees, 1},   {"tan", Op::TanDegrees, 1},
    {"asin", Op::AsinDegrees, 1}, {"acos", Op::AcosDegrees, 1}, {"atan", Op::AtanDegrees, 1},
    {"atan2", Op::Atan2Cpfg, 2},  {"fabs", Op::Abs, 1},         {"sign", Op::Sign, 1},
    {"trunc", Op::Round, 1},      {"srand", Op::Srand, 1},
};

// cpfg's func(id, x): the id-th function of the object's function files at
// x (Měch 2005, "CPFG Version 4.0 User's Manual", §5.5 and §8.1.6). Known
// only where the scope has a table of them.
constexpr Function kFunc{"func", Op::Func, 2};

// cpfg's functions that need what plantfield does not have: files, sound,
// a window, contours from the object's files, a communicating environment
// program, or its other random distributions.
constexpr std::string_view kUnsupportedCpfgFunctions[] = {
    "fopen",  "fclose", "fflush", "fprintf", "fscanf",   "play",   "display",        "stop",
    "inblob", "curveX", "curveY", "curveZ",  "curveGAL", "vvxmin", "vvxmax",         "vvymin",
    "vvymax", "vvzmin", "vvzmax", "vvscale", "bran",     "biran",  "setDerivLength", "getDerivLength",
};

// Whether an instruction reads what may change from one evaluation to the
// next: parameters, globals, random draws (folding stops at it).
bool readsVaryingValues(Op op) {
    switch (op) {
    case Op::Var:
    case Op::Global:
    case Op::Element:
    case Op::Ran:
    case Op::NRan:
    case Op::Srand: return true;
    default: return false;
    }
}

// Whether code computes the same value every time without the function
// files: no varying value and no func.
bool isConstantCode(std::span<const Instruction> code) {
    return std::none_of(code.begin(), code.end(), [](const Instruction& instruction) {
        return readsVaryingValues(instruction.op) || instruction.op == Op::Func;
    });
}

// cpfg's SplineFuncValue (splinefun.cpp): the id is converted to int and
// counts from 1; an id outside the table gives 0.
double callFunction(const FunctionTable& table, double id, double x) {
    if (!table || !std::isfinite(id)) return 0.0;
    const double index = std::trunc(id) - 1.0;
    if (index < 0.0 || index >= static_cast<double>(table->size())) return 0.0;
    return (*table)[static_cast<size_t>(index)](x);
}

const Function* findFunction(std::string_view name, Arithmetic arithmetic) {
    if (arithmetic == Arithmetic::Cpfg)
        for (const Function& function : kCpfgFunctions)
            if (function.name == name) return &function;
    for (const Function& function : kFunctions)
        if (function.name == name) return &function;
    return nullptr;
}

// Net effect of each instruction on the stack depth.
int stackEffect(Op op) {
    switch (op) {
    case Op::Const:
    case Op::Var:
    case Op::Global: return 1;
    case Op::Element:
    case Op::Int:
    case Op::SinDegrees:
    case Op::CosDegrees:
    case Op::TanDegrees:
    case Op::AsinDegrees:
    case Op::AcosDegrees:
    case Op::AtanDegrees:
    case Op::Sign:
    case Op::Round:
    case Op::Srand:
    case Op::Neg:
    case Op::Not:
    case Op::Sin:
    case Op::Cos:
    case Op::Tan:
    case Op::Asin:
    case Op::Acos:
    case Op::Atan:
    case Op::Sqrt:
    case Op::Exp:
    case Op::Log:
    case Op::Abs:
    case Op::Floor:
    case Op::Ceil:
    case Op::Ran: return 0;
    case Op::Select:
    case Op::Clamp: return -2;
    default: return -1;
    }
}

// Binary operators by precedence level, lowest first; '?:' sits below them all.
struct Binary {
    std::string_view token;
    Op op;
    int precedence;
};
constexpr Binary kBinaries[] = {
    {"||", Op::Or, 1}, {"&&", Op::And, 2}, {"==", Op::Eq, 3}, {"!=", Op::Ne, 3}, {"<=", Op::Le, 4},
    {">=", Op::Ge, 4}, {"<", Op::Lt, 4},   {">", Op::Gt, 4},  {"+", Op::Add, 5}, {"-", Op::Sub, 5},
    {"*", Op::Mul, 6}, {"/", Op::Div, 6},  {"%", Op::Mod, 6},
};

struct Compiler {
    Cursor& cursor;
    const ExpressionScope& scope;
    const std::string& file;
    std::vector<Diagnostic>& diagnostics;
    Expression out;
    int depth = 0;
    int maxDepth = 0;
    bool failed = false;
    bool usesVariablesOrRandom = false;

    void emit(Instruction instruction) {
        out.code.push_back(instruction);
        depth += stackEffect(instruction.op);
        maxDepth = std::max(maxDepth, depth);
        if (readsVaryingValues(instruction.op)) usesVariablesOrRandom = true;
        if (instruction.op == Op::Func) out.functions = scope.functions;
    }

    bool hasFunctions() const { return scope.functions && !scope.functions->empty(); }

    // A func id that is the same every time must name one of the functions.
    void checkFunctionId(size_t begin, size_t at) {
        const std::span<const Instruction> code(out.code.begin() + static_cast<std::ptrdiff_t>(begin), out.code.end());
        if (!isConstantCode(code)) return;
        RandomStream unused;
        const double id = evaluate(Expression{{code.begin(), code.end()}, nullptr}, nullptr, unused);
        const size_t count = scope.functions->size();
        if (std::isfinite(id) && std::trunc(id) >= 1.0 && std::trunc(id) <= static_cast<double>(count)) return;
        cursor.pos = at;
        char shown[32];
        std::snprintf(shown, sizeof shown, "%g", id);
        fail(std::string("func(") + shown + ", x) names no function: the object's view file names " +
                 std::to_string(count) + " function" + (count == 1 ? "" : "s"),
             "an id from 1 to " + std::to_string(count));
    }

    void fail(std::string message, std::string expected = {}) {
        if (!failed) diagnostics.push_back(errorAt(cursor, file, std::move(message), std::move(expected)));
        failed = true;
    }

    const Binary* peekBinary() {
        cursor.skipSpaces();
        if (cursor.atArrow()) return nullptr; // "x > 0 --> ..." : the '-' begins the arrow
        for (const Binary& binary : kBinaries)
            if (cursor.startsWith(binary.token)) return &binary;
        return nullptr;
    }

    // expression := binary ('?' expression ':' expression)?
    void expression(int nesting) {
        if (nesting > kMaxNesting) return fail("expression nested too deeply");
        binary(1, nesting);
        if (failed) return;
        cursor.skipSpaces();
        if (cursor.peek() == '?') {
            cursor.accept("?");
            expression(nesting + 1);
            if (failed) return;
            cursor.skipSpaces();
            if (!cursor.accept(":")) return fail("incomplete conditional expression", "':'");
            expression(nesting + 1);
            emit({Op::Select});
        }
    }

    void binary(int minPrecedence, int nesting) {
        unary(nesting);
        while (!failed) {
            const Binary* binary = peekBinary();
            if (!binary || binary->precedence < minPrecedence) return;
            cursor.pos += binary->token.size();
            this->binary(binary->precedence + 1, nesting);
            const bool cpfg = scope.arithmetic == Arithmetic::Cpfg;
            emit({cpfg && binary->op == Op::Div   ? Op::DivCpfg
                  : cpfg && binary->op == Op::Mod ? Op::ModInt
                                                  : binary->op});
        }
    }

    void unary(int nesting) {
        if (nesting > kMaxNesting) return fail("expression nested too deeply");
        cursor.skipSpaces();
        if (cursor.peek() == '-' && !cursor.atArrow()) {
            cursor.accept("-");
            unary(nesting + 1);
            emit({Op::Neg});
        } else if (cursor.peek() == '+') {
            cursor.accept("+");
            unary(nesting + 1);
        } else if (cursor.peek() == '!' && cursor.peek(1) != '=') {
            cursor.accept("!");
            unary(nesting + 1);
            emit({Op::Not});
        } else {
            power(nesting);
        }
    }

    // Right-associative and tighter than unary minus: -2^2 is -4.
    void power(int nesting) {
        primary(nesting);
        cursor.skipSpaces();
        if (!failed && cursor.peek() == '^') {
            cursor.accept("^");
            unary(nesting + 1);
            emit({Op::Pow});
        }
    }

    void number() {
        size_t begin = cursor.pos;
        while (std::isdigit(static_cast<unsigned char>(cursor.peek())) || cursor.peek() == '.') ++cursor.pos;
        if ((cursor.peek() == 'e' || cursor.peek() == 'E') &&
            (std::isdigit(static_cast<unsigned char>(cursor.peek(1))) ||
             ((cursor.peek(1) == '-' || cursor.peek(1) == '+') &&
              std::isdigit(static_cast<unsigned char>(cursor.peek(2)))))) {
            cursor.pos += 2;
            while (std::isdigit(static_cast<unsigned char>(cursor.peek()))) ++cursor.pos;
        }
        std::string_view text = cursor.text.substr(begin, cursor.pos - begin);
        double value = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) {
            cursor.pos = begin;
            return fail("malformed number '" + std::string(text) + "'");
        }
        emit({Op::Const, 0, 0, value});
    }

    void call(const Function& function, int nesting) {
        cursor.skipSpaces();
        if (!cursor.accept("(")) return fail("function '" + std::string(function.name) + "' needs arguments", "'('");
        for (int argument = 0; argument < function.arity; ++argument) {
            if (argument > 0) {
                cursor.skipSpaces();
                if (!cursor.accept(","))
                    return fail("function '" + std::string(function.name) + "' takes " +
                                    std::to_string(function.arity) + " arguments",
                                "','");
            }
            cursor.skipSpaces();
            const size_t begin = out.code.size(), at = cursor.pos;
            expression(nesting + 1);
            if (!failed && function.op == Op::Func && argument == 0) checkFunctionId(begin, at);
            if (failed) return;
        }
        cursor.skipSpaces();
        if (!cursor.accept(")"))
            return fail("function '" + std::string(function.name) + "' takes " + std::to_string(function.arity) +
                            " argument" + (function.arity > 1 ? "s" : ""),
                        "')'");
        emit({function.op});
    }

    // A scalar global, or an element of a global array: name[i][j] reads
    // slot + (int)i * extent(j) + (int)j, as C lays out its arrays.
    void globalValue(const GlobalVariable& global, int nesting) {
        if (global.extents.empty()) return emit({Op::Global, 0, 0, double(global.slot)});
        for (size_t dimension = 0; dimension < global.extents.size(); ++dimension) {
            cursor.skipSpaces();
            if (!cursor.accept("["))
                return fail("'" + global.name + "' is an array of " + std::to_string(global.extents.size()) +
                                " dimension" + (global.extents.size() > 1 ? "s" : ""),
                            "'['");
            if (dimension > 0) {
                emit({Op::Const, 0, 0, double(global.extents[dimension])});
                emit({Op::Mul});
            }
            expression(nesting + 1);
            if (failed) return;
            emit({Op::Int});
            if (dimension > 0) emit({Op::Add});
            cursor.skipSpaces();
            if (!cursor.accept("]")) return fail("unclosed array index", "']'");
        }
        emit({Op::Element, 0, global.size(), double(global.slot)});
    }

    void primary(int nesting) {
        cursor.skipSpaces();
        char c = cursor.peek();
        if (std::isdigit(static_cast<unsigned char>(c)) ||
            (c == '.' && std::isdigit(static_cast<unsigned char>(cursor.peek(1))))) {
            number();
        } else if (c == '(') {
            cursor.accept("(");
            expression(nesting + 1);
            if (failed) return;
            cursor.skipSpaces();
            if (!cursor.accept(")")) fail("unbalanced parenthesis", "')'");
        } else if (isIdentifierStart(c)) {
            size_t begin = cursor.pos;
            std::string name(cursor.identifier());
            if (const Function* function = findFunction(name, scope.arithmetic)) return call(*function, nesting);
            if (name == kFunc.name && hasFunctions()) return call(kFunc, nesting);
            for (size_t i = 0; i < scope.variables.size(); ++i)
                if (scope.variables[i] == name) return emit({Op::Var, static_cast<uint16_t>(i)});
            if (scope.globals)
                if (const GlobalVariable* global = scope.globals->find(name)) return globalValue(*global, nesting);
            if (scope.constants)
                if (auto found = scope.constants->find(name); found != scope.constants->end())
                    return emit({Op::Const, 0, 0, found->second});
            cursor.pos = begin;
            if (name == kFunc.name)
                return fail("func(id, x) reads the object's function files, and no function files are given",
                            "a vlab object whose view file names them ('function: FILE')");
            for (std::string_view unsupported : kUnsupportedCpfgFunctions)
                if (unsupported == name) return fail("cpfg's function '" + name + "' is not supported");
            fail("unknown name '" + name + "'", "a parameter of this production, a #define constant or a function");
        } else {
            fail(cursor.atEnd() ? "expression ends too early" : std::string("unexpected '") + c + "' in expression",
                 "a number, a name, '(' or a unary operator");
        }
    }
};

} // namespace

std::optional<Expression> parseExpression(Cursor& cursor, const ExpressionScope& scope, const std::string& file,
                                          std::vector<Diagnostic>& diagnostics) {
    Compiler compiler{cursor, scope, file, diagnostics};
    compiler.expression(0);
    if (!compiler.failed && compiler.maxDepth > kMaxStack) compiler.fail("expression too complex to evaluate");
    if (compiler.failed) return std::nullopt;
    // Fold expressions of constants only, so "#define" arithmetic costs nothing per module.
    if (!compiler.usesVariablesOrRandom && compiler.out.code.size() > 1) {
        RandomStream unused;
        double value = evaluate(compiler.out, nullptr, unused);
        compiler.out = {{{Op::Const, 0, 0, value}}, nullptr};
    }
    return std::move(compiler.out);
}

uint32_t GlobalVariable::size() const {
    uint64_t size = 1;
    for (uint32_t extent : extents) size = std::min<uint64_t>(size * extent, kMaxGlobalSlots + 1);
    return static_cast<uint32_t>(size);
}

const GlobalVariable* GlobalTable::find(std::string_view name) const {
    for (const GlobalVariable& variable : variables)
        if (variable.name == name) return &variable;
    return nullptr;
}

const GlobalVariable* GlobalTable::add(std::string name, std::vector<uint32_t> extents) {
    GlobalVariable variable{std::move(name), static_cast<uint32_t>(initial.size()), std::move(extents)};
    if (initial.size() + variable.size() > kMaxGlobalSlots) return nullptr;
    initial.resize(initial.size() + variable.size(), 0.0);
    variables.push_back(std::move(variable));
    return &variables.back();
}

bool hasSideEffects(const Expression& expression) {
    return std::any_of(expression.code.begin(), expression.code.end(),
                       [](const Instruction& instruction) { return instruction.op == Op::Srand; });
}

double evaluate(const Expression& expression, const double* variables, RandomStream& random, const double* globals) {
    constexpr double kDegrees = 180.0 / 3.14159265358979323846;
    double stack[kMaxStack];
    int top = -1; // index of the top element
    for (const Instruction& instruction : expression.code) {
        double& a = stack[top > 0 ? top - 1 : 0]; // second from the top, for binary operators
        double& t = stack[top >= 0 ? top : 0];
        switch (instruction.op) {
        case Op::Const: stack[++top] = instruction.value; break;
        case Op::Var: stack[++top] = variables[instruction.variable]; break;
        case Op::Neg: t = -t; break;
        case Op::Not: t = t == 0.0 ? 1.0 : 0.0; break;
        case Op::Add:
            a = a + t;
            --top;
            break;
        case Op::Sub:
            a = a - t;
            --top;
            break;
        case Op::Mul:
            a = a * t;
            --top;
            break;
        case Op::Div:
            a = a / t;
            --top;
            break;
        case Op::Pow:
            a = std::pow(a, t);
            --top;
            break;
        case Op::Mod:
            a = std::fmod(a, t);
            --top;
            break;
        case Op::Lt:
            a = a < t;
            --top;
            break;
        case Op::Le:
            a = a <= t;
            --top;
            break;
        case Op::Gt:
            a = a > t;
            --top;
            break;
        case Op::Ge:
            a = a >= t;
            --top;
            break;
        case Op::Eq:
            a = a == t;
            --top;
            break;
        case Op::Ne:
            a = a != t;
            --top;
            break;
        case Op::And:
            a = (a != 0.0 && t != 0.0);
            --top;
            break;
        case Op::Or:
            a = (a != 0.0 || t != 0.0);
            --top;
            break;
        case Op::Select:
            stack[top - 2] = stack[top - 2] != 0.0 ? stack[top - 1] : stack[top];
            top -= 2;
            break;
        case Op::Sin: t = std::sin(t); break;
        case Op::Cos: t = std::cos(t); break;
        case Op::Tan: t = std::tan(t); break;
        case Op::Asin: t = std::asin(t); break;
        case Op::Acos: t = std::acos(t); break;
        case Op::Atan: t = std::atan(t); break;
        case Op::Atan2:
            a = std::atan2(a, t);
            --top;
            break;
        case Op::Sqrt: t = std::sqrt(t); break;
        case Op::Exp: t = std::exp(t); break;
        case Op::Log: t = std::log(t); break;
        case Op::Abs: t = std::fabs(t); break;
        case Op::Floor: t = std::floor(t); break;
        case Op::Ceil: t = std::ceil(t); break;
        case Op::Min:
            a = std::min(a, t);
            --top;
            break;
        case Op::Max:
            a = std::max(a, t);
            --top;
            break;
        case Op::Clamp:
            stack[top - 2] = std::clamp(stack[top - 2], std::min(stack[top - 1], t), std::max(stack[top - 1], t));
            top -= 2;
            break;
        case Op::Ran: t = t * random.uniform(); break;
        case Op::NRan:
            a = random.normal(a, t);
            --top;
            break;
        case Op::Global: stack[++top] = globals[static_cast<size_t>(instruction.value)]; break;
        case Op::Element:
            t = t >= 0 && t < instruction.extent
                    ? globals[static_cast<size_t>(instruction.value) + static_cast<size_t>(t)]
                    : 0.0;
            break;
        case Op::Int: t = std::isfinite(t) ? std::clamp(std::trunc(t), -2147483648.0, 2147483647.0) : 0.0; break;
        case Op::SinDegrees: t = std::sin(t / kDegrees); break;
        case Op::CosDegrees: t = std::cos(t / kDegrees); break;
        case Op::TanDegrees: t = std::tan(t / kDegrees); break;
        case Op::AsinDegrees: t = std::asin(t) * kDegrees; break;
        case Op::AcosDegrees: t = std::acos(t) * kDegrees; break;
        case Op::AtanDegrees: t = std::atan(t) * kDegrees; break;
        case Op::Atan2Cpfg:
            a = std::atan2(t, a) * kDegrees;
            --top;
            break;
        case Op::DivCpfg:
            a = t == 0.0 ? a : a / t;
            --top;
            break;
        case Op::ModInt: {
            const double divisor = std::isfinite(t) ? std::trunc(t) : 0.0;
            const double dividend = std::isfinite(a) ? std::trunc(a) : 0.0;
            a = divisor == 0.0 || std::fabs(divisor) > 2147483647.0 || std::fabs(dividend) > 2147483647.0
                    ? 0.0
                    : static_cast<double>(static_cast<int64_t>(dividend) % static_cast<int64_t>(divisor));
            --top;
            break;
        }
        case Op::Sign: t = t == 0.0 ? 0.0 : (t > 0.0 ? 1.0 : -1.0); break;
        case Op::Round: t = std::floor(t + 0.5); break;
        case Op::Srand:
            random =
                RandomStream::forModule(static_cast<uint64_t>(static_cast<int64_t>(std::isfinite(t) ? t : 0.0)), 0, 0);
            t = 0.0;
            break;
        case Op::Func:
            a = callFunction(expression.functions, a, t);
            --top;
            break;
        }
    }
    return top >= 0 ? stack[top] : 0.0;
}

} // namespace lsys
