#include "lsystem/language/statements.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "lsystem/common/error.h"

namespace lsys {

namespace {

constexpr int kMaxBlockNesting = 64;

struct BlockParser {
    Cursor& cursor;
    BlockScope& scope;
    const std::string& file;
    std::vector<Diagnostic>& diagnostics;

    bool fail(std::string message, std::string expected = {}) {
        diagnostics.push_back(errorAt(cursor, file, std::move(message), std::move(expected)));
        return false;
    }

    ExpressionScope expressionScope() const {
        static const std::vector<std::string> none;
        return {scope.locals ? *scope.locals : none, scope.constants, scope.globals, scope.arithmetic, scope.functions};
    }

    bool expression(Expression& out) {
        std::optional<Expression> parsed = parseExpression(cursor, expressionScope(), file, diagnostics);
        if (!parsed) return false;
        out = std::move(*parsed);
        return true;
    }

    bool expect(std::string_view token, const std::string& what) {
        cursor.skipSpaces();
        if (cursor.accept(token)) return true;
        std::string quoted(1, '\'');
        quoted.append(token);
        quoted += '\'';
        return fail("expected " + quoted + " " + what, quoted);
    }

    // "(condition)" after if and while.
    bool condition(Expression& out, std::string_view keyword) {
        return expect("(", "after " + std::string(keyword)) && expression(out) &&
               expect(")", "after the condition of " + std::string(keyword));
    }

    // Whether the cursor is at `keyword` as a whole word; consumes it if so.
    bool keyword(std::string_view word) {
        cursor.skipSpaces();
        if (!cursor.startsWith(word) || isIdentifierChar(cursor.peek(word.size()))) return false;
        cursor.pos += word.size();
        return true;
    }

    std::optional<Block> block(int nesting) {
        if (nesting > kMaxBlockNesting) {
            fail("statement blocks nested too deeply");
            return std::nullopt;
        }
        if (!expect("{", "to open a statement block")) return std::nullopt;
        Block out;
        while (true) {
            cursor.skipSpaces();
            if (cursor.accept("}")) return out;
            if (cursor.atEnd()) {
                fail("statement block not closed", "'}'");
                return std::nullopt;
            }
            BlockStatement statement;
            if (!this->statement(statement, nesting)) return std::nullopt;
            if (statement.kind != BlockStatement::Kind::Evaluate || !statement.value.code.empty())
                out.push_back(std::move(statement));
        }
    }

    bool nested(std::vector<BlockStatement>& into, int nesting) {
        std::optional<Block> inner = block(nesting + 1);
        if (!inner) return false;
        into = std::move(*inner);
        return true;
    }

    bool statement(BlockStatement& out, int nesting) {
        if (keyword("if")) {
            out.kind = BlockStatement::Kind::If;
            if (!condition(out.value, "if") || !nested(out.body, nesting)) return false;
            return !keyword("else") || nested(out.otherwise, nesting);
        }
        if (keyword("while")) {
            out.kind = BlockStatement::Kind::While;
            return condition(out.value, "while") && nested(out.body, nesting);
        }
        if (keyword("do")) {
            out.kind = BlockStatement::Kind::DoWhile;
            if (!nested(out.body, nesting)) return false;
            if (!keyword("while")) return fail("'do { ... }' needs its condition", "'while (condition);'");
            return condition(out.value, "do ... while") && expect(";", "after do ... while");
        }
        if (keyword("printf")) return print(out);
        if (keyword("array")) return arrays();
        if (keyword("external")) // cpfg's variables shared with a separate program over a socket
            return fail("cpfg's 'external' variables are not supported", "an assignment, if, while, do or printf");
        const size_t begin = cursor.pos;
        std::string name(cursor.identifier());
        if (!name.empty()) {
            cursor.skipSpaces();
            if (cursor.peek() == '[' || (cursor.peek() == '=' && cursor.peek(1) != '='))
                return assignment(out, name, begin);
        }
        cursor.pos = begin;
        out.kind = BlockStatement::Kind::Evaluate;
        return expression(out.value) && expect(";", "after the statement");
    }

    // name = value;  name[i][j] = value;
    bool assignment(BlockStatement& out, const std::string& name, size_t begin) {
        out.kind = BlockStatement::Kind::Assign;
        if (!target(out, name, begin)) return false;
        cursor.skipSpaces();
        if (!cursor.accept("=")) return fail("expected '=' after '" + name + "'", "'='");
        return expression(out.value) && expect(";", "after the assignment");
    }

    // Where an assignment writes: a known local, a known global, or a new
    // variable of the block's kind (cpfg's LHS rule).
    bool target(BlockStatement& out, const std::string& name, size_t begin) {
        if (scope.locals)
            for (size_t i = 0; i < scope.locals->size(); ++i)
                if ((*scope.locals)[i] == name) {
                    out.slot = static_cast<uint32_t>(i);
                    return notIndexed(name);
                }
        if (const GlobalVariable* global = scope.globals ? scope.globals->find(name) : nullptr) {
            out.storage = Storage::Global;
            out.slot = global->slot;
            if (global->extents.empty()) return notIndexed(name);
            out.extent = global->size();
            // The flat index is read as an element read would be: parse "name[..]" as a value
            // and keep its index computation (everything before the final Element).
            cursor.pos = begin;
            Expression element;
            if (!expression(element)) return false;
            if (element.code.empty() || element.code.back().op != Op::Element)
                return fail("'" + name + "' is an array", "'" + name + "[index]'");
            element.code.pop_back();
            out.index = std::move(element);
            return true;
        }
        if (scope.locals) {
            if (scope.locals->size() >= kMaxVariables) return fail("too many variables in one production");
            out.slot = static_cast<uint32_t>(scope.locals->size());
            scope.locals->push_back(name);
        } else {
            const GlobalVariable* added = scope.globals->add(name);
            if (!added) return fail("too many global variables");
            out.storage = Storage::Global;
            out.slot = added->slot;
        }
        return notIndexed(name);
    }

    bool notIndexed(const std::string& name) {
        cursor.skipSpaces();
        return cursor.peek() != '[' || fail("'" + name + "' is not an array", "'='");
    }

    // printf("format", values...);
    bool print(BlockStatement& out) {
        out.kind = BlockStatement::Kind::Print;
        if (!expect("(", "after printf")) return false;
        cursor.skipSpaces();
        if (!cursor.accept("\"")) return fail("printf needs a format string", "a string in double quotes");
        while (!cursor.atEnd() && cursor.peek() != '"') {
            char c = cursor.text[cursor.pos++];
            if (c == '\\' && !cursor.atEnd()) {
                const char escaped = cursor.text[cursor.pos++];
                c = escaped == 'n' ? '\n' : escaped == 't' ? '\t' : escaped;
            }
            out.format += c;
        }
        if (!cursor.accept("\"")) return fail("unterminated string", "'\"'");
        while (true) {
            cursor.skipSpaces();
            if (cursor.accept(")")) break;
            if (!cursor.accept(",")) return fail("malformed printf arguments", "',' or ')'");
            out.arguments.emplace_back();
            if (!expression(out.arguments.back())) return false;
        }
        return expect(";", "after printf");
    }

    // cpfg's define: block: array a[2][3] = {1, 2, 3, 4, 5, 6}, b[4];
    bool arrays() {
        if (!scope.arrayDefinitions)
            return fail("arrays are defined in the 'define:' block", "an assignment, if, while, do or printf");
        while (true) {
            cursor.skipSpaces();
            std::string name(cursor.identifier());
            if (name.empty()) return fail("missing array name", "a name");
            if (scope.globals->find(name)) return fail("'" + name + "' is already defined");
            std::vector<uint32_t> extents;
            while ((cursor.skipSpaces(), cursor.accept("["))) {
                std::optional<double> extent = constant();
                if (!extent) return false;
                if (!(*extent >= 1 && *extent <= kMaxGlobalSlots))
                    return fail("invalid array size", "a positive integer");
                extents.push_back(static_cast<uint32_t>(*extent));
                if (!expect("]", "after the array size")) return false;
            }
            if (extents.empty()) return fail("'" + name + "' needs its size", "'[size]'");
            const GlobalVariable* array = scope.globals->add(name, extents);
            if (!array) return fail("arrays too large", "at most " + std::to_string(kMaxGlobalSlots) + " elements");
            cursor.skipSpaces();
            if (cursor.accept("=") && !initialiser(*array)) return false;
            cursor.skipSpaces();
            if (cursor.accept(";")) return true;
            if (!cursor.accept(",")) return fail("malformed array definition", "',' or ';'");
        }
    }

    bool initialiser(const GlobalVariable& array) {
        if (!expect("{", "to open the array's values")) return false;
        for (uint32_t i = 0;; ++i) {
            cursor.skipSpaces();
            if (cursor.accept("}")) return true;
            if (i > 0 && !cursor.accept(",")) return fail("malformed array values", "',' or '}'");
            if (i >= array.size()) return fail("more values than '" + array.name + "' holds");
            std::optional<double> value = constant();
            if (!value) return false;
            scope.globals->initial[array.slot + i] = *value;
        }
    }

    std::optional<double> constant() {
        ExpressionScope constants{{}, scope.constants, nullptr, scope.arithmetic, scope.functions};
        std::optional<Expression> parsed = parseExpression(cursor, constants, file, diagnostics);
        if (!parsed) return std::nullopt;
        RandomStream random;
        return evaluate(*parsed, nullptr, random);
    }
};

// printf with cpfg's rule: one value per conversion, in order. Each
// conversion is checked and given the type it prints, so a format from a
// plant file cannot read memory it does not own (%s, %n and the like are
// written out as they are).
void print(const BlockStatement& statement, const double* locals, double* globals, RandomStream& random) {
    std::string out;
    size_t next = 0;
    const std::string& format = statement.format;
    for (size_t i = 0; i < format.size(); ++i) {
        if (format[i] != '%') {
            out += format[i];
            continue;
        }
        size_t end = i + 1;
        while (end < format.size() && std::strchr("-+ #0", format[end])) ++end;
        while (end < format.size() && (std::isdigit(static_cast<unsigned char>(format[end])) || format[end] == '.'))
            ++end;
        const char conversion = end < format.size() ? format[end] : '\0';
        if (conversion == '%') {
            out += '%';
            i = end;
            continue;
        }
        if (!conversion || !std::strchr("diouxXeEfFgGaAc", conversion) || end - i > 16) {
            out += '%';
            continue;
        }
        const double value =
            next < statement.arguments.size() ? evaluate(statement.arguments[next++], locals, random, globals) : 0.0;
        char piece[128];
        const std::string spec = format.substr(i, end - i);
        if (std::strchr("eEfFgGaA", conversion))
            std::snprintf(piece, sizeof piece, (spec + conversion).c_str(), value);
        else if (conversion == 'c')
            std::snprintf(piece, sizeof piece, (spec + 'c').c_str(), static_cast<int>(value));
        else
            std::snprintf(piece, sizeof piece, (spec + "ll" + conversion).c_str(),
                          static_cast<long long>(std::isfinite(value) ? std::clamp(value, -9.2e18, 9.2e18) : 0.0));
        out += piece;
        i = end;
    }
    std::fputs(out.c_str(), stderr);
}

struct Runner {
    double* locals;
    double* globals;
    RandomStream& random;
    uint64_t iterations = 0;

    bool test(const Expression& condition) { return evaluate(condition, locals, random, globals) != 0.0; }

    void iterate() {
        if (++iterations > kMaxLoopIterations)
            throw DerivationError("a loop in a statement block ran " + std::to_string(kMaxLoopIterations) +
                                  " times without ending");
    }

    void run(const Block& block) {
        for (const BlockStatement& statement : block) {
            switch (statement.kind) {
            case BlockStatement::Kind::Assign: assign(statement); break;
            case BlockStatement::Kind::If: run(test(statement.value) ? statement.body : statement.otherwise); break;
            case BlockStatement::Kind::While:
                while (test(statement.value)) {
                    iterate();
                    run(statement.body);
                }
                break;
            case BlockStatement::Kind::DoWhile:
                do {
                    iterate();
                    run(statement.body);
                } while (test(statement.value));
                break;
            case BlockStatement::Kind::Evaluate: evaluate(statement.value, locals, random, globals); break;
            case BlockStatement::Kind::Print: print(statement, locals, globals, random); break;
            }
        }
    }

    void assign(const BlockStatement& statement) {
        const double value = evaluate(statement.value, locals, random, globals);
        if (statement.storage == Storage::Local) {
            locals[statement.slot] = value;
            return;
        }
        size_t element = 0;
        if (statement.index) {
            const double index = evaluate(*statement.index, locals, random, globals);
            if (!(index >= 0 && index < statement.extent)) return; // outside the array: nothing is written
            element = static_cast<size_t>(index);
        }
        globals[statement.slot + element] = value;
    }
};

} // namespace

std::optional<Block> parseBlock(Cursor& cursor, BlockScope& scope, const std::string& file,
                                std::vector<Diagnostic>& diagnostics) {
    return BlockParser{cursor, scope, file, diagnostics}.block(0);
}

void runBlock(const Block& block, double* locals, double* globals, RandomStream& random) {
    Runner{locals, globals, random}.run(block);
}

} // namespace lsys
