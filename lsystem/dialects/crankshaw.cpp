// Crankshaw 2020: statements '#...;', several per line allowed.
//   #n = 6;                       derivation length: 6
//   #define r {10, 20};           #define r (10+ran(20-10))      (drawn once)
//   #object F BRANCH;             // object F: BRANCH             (the turtle draws no objects yet)
//   #w : !(w) Z;                  Axiom: !(w) Z
//   #p1 : F(s, x) : * : F(s, x);  p1: F(s,x) --> F(s,x)
//   #p2 : A(x) : ~0.33 : B;       p2: A(x) --> B : 0.33
//   #p3 : F(1, sc) : * : ...;     p3: F(_c1,sc) : _c1==1 --> ...  (a literal parameter becomes a condition)
// Names are [A-Za-z_][A-Za-z0-9_]*, so multi-letter modules are separated by
// spaces and declared with 'module'. F(length, spring constant) and
// !(width, ring resolution) keep their parameters in the derived string; an
// appended interpretation section turns them into F(l) with @K(k) and !(w).

#include <cctype>
#include <optional>

#include "lsystem/dialects/native_text.h"

namespace lsys {

namespace {

// Single-character modules besides names (ABOP turtle symbols; the thesis'
// wording swaps pitch and roll relative to ABOP although its examples come from
// ABOP, so it is not followed).
constexpr std::string_view kSymbols = "+-/\\^&$[]!|'%.";

struct Crankshaw {
    const Source& source;
    NativeText out{source};
    ModuleNames names;
    std::vector<Diagnostic> diagnostics;
    int rangeDepth = 0; // bounds the recursion of range() and expression()

    bool fail(size_t offset, std::string message, std::string expected = {}) {
        diagnostics.push_back(source.diagnostic(offset, std::move(message), std::move(expected)));
        return false;
    }

    bool expect(Scanner& s, char c) {
        s.skipSpaces();
        if (s.accept(std::string_view(&c, 1))) return true;
        return fail(s.pos, s.atLineEnd() ? "statement ends early" : std::string("unexpected '") + s.peek() + "'",
                    std::string("'") + c + "'");
    }

    // An expression up to one of stops at parenthesis depth 0, with {a,b}
    // ranges rewritten as a + ran(b - a). Stops at ';' and line ends anyway.
    bool expression(Scanner& s, std::string_view stops, Statement& into) {
        s.skipSpaces();
        size_t begin = s.pos;
        int depth = 0;
        while (!s.atLineEnd() && s.peek() != ';' && !(depth == 0 && stops.find(s.peek()) != std::string_view::npos)) {
            char c = s.peek();
            if (c == '{') {
                if (!range(s, into)) return false;
                continue;
            }
            if (c == '(') ++depth;
            if (c == ')') --depth;
            into.copy(std::string_view(&c, 1), s.pos++);
        }
        if (s.pos == begin) return fail(s.pos, "missing expression", "a number, a name or an expression");
        return true;
    }

    bool range(Scanner& s, Statement& into) {
        size_t open = s.pos++;
        if (rangeDepth >= 16) return fail(open, "random ranges nested too deeply", "at most 16 levels");
        ++rangeDepth;
        bool ok = rangeBody(s, open, into);
        --rangeDepth;
        return ok;
    }

    bool rangeBody(Scanner& s, size_t open, Statement& into) {
        Statement low, high;
        if (!expression(s, ",}", low)) return false;
        if (s.accept("}")) { // {a} is the single value a
            into.emit("(", open), into.append(low), into.emit(")", open);
            return true;
        }
        if (!expect(s, ',') || !expression(s, "}", high)) return false;
        if (!s.accept("}")) return fail(s.pos, "unclosed random range", "'}'");
        into.emit("((", open), into.append(low), into.emit(")+ran((", open), into.append(high);
        into.emit(")-(", open), into.append(low), into.emit(")))", open);
        return true;
    }

    // One module name: a name or a turtle symbol. Empty when none starts here.
    std::string_view moduleName(Scanner& s) {
        size_t begin = s.pos;
        std::string_view name = s.identifier();
        if (name.empty() && kSymbols.find(s.peek()) != std::string_view::npos && s.peek() != '\0')
            name = std::string_view(source.text).substr(s.pos++, 1);
        if (!name.empty()) names.use(name, begin);
        return name;
    }

    // Modules up to ';' (or ':' when stopAtColon). Predecessor parameters must
    // be names or numbers; a number becomes a formal parameter _cN and an
    // equality added to literalConditions.
    bool modules(Scanner& s, Statement& into, bool predecessor, Statement* literalConditions = nullptr) {
        int count = 0;
        while (true) {
            s.skipSpaces();
            if (s.atLineEnd() || s.peek() == ';' || (predecessor && s.peek() == ':')) break;
            size_t begin = s.pos;
            std::string_view name = moduleName(s);
            if (name.empty())
                return fail(s.pos, std::string("unexpected '") + s.peek() + "'", "a module name or a turtle symbol");
            if (count++ > 0) into.emit(" ", begin);
            into.copy(name, begin);
            size_t beforeSpaces = s.pos;
            s.skipSpaces();
            if (!s.accept("(")) { // "F (1)" is F(1), as the thesis writes "- (r)Z"
                s.pos = beforeSpaces;
                continue;
            }
            into.emit("(", s.pos - 1);
            for (int parameter = 0;; ++parameter) {
                s.skipSpaces();
                if (s.accept(")")) break;
                if (parameter > 0) {
                    if (!s.accept(",")) return fail(s.pos, "malformed parameter list", "',' or ')'");
                    into.emit(",", s.pos - 1);
                }
                bool ok =
                    predecessor ? formalParameter(s, parameter, into, *literalConditions) : expression(s, ",)", into);
                if (!ok) return false;
            }
            into.emit(")", s.pos - 1);
        }
        if (predecessor && count != 1)
            return fail(s.pos, count == 0 ? "missing predecessor" : "a predecessor is one module",
                        "one module such as F(x)");
        return true;
    }

    // The name of a literal's formal depends only on its place, so stochastic
    // alternatives with the same literal predecessor stay one native group.
    bool formalParameter(Scanner& s, int index, Statement& into, Statement& literalConditions) {
        s.skipSpaces();
        size_t begin = s.pos;
        std::string_view name = s.identifier();
        if (!name.empty()) {
            into.copy(name, begin);
            return true;
        }
        bool negative = s.accept("-");
        std::string_view literal = s.number();
        if (literal.empty())
            return fail(begin, "a predecessor parameter must be a name or a number", "a name such as 'x'");
        std::string formal = "_c" + std::to_string(index + 1);
        into.emit(formal, begin);
        if (!literalConditions.text.empty()) literalConditions.emit(" && ", begin);
        literalConditions.emit(formal + "==" + (negative ? "-" : ""), begin);
        literalConditions.copy(literal, begin + (negative ? 1 : 0));
        return true;
    }

    // #n = N;
    bool generations(Scanner& s, size_t at) {
        Statement st = out.start(at);
        st.emit("derivation length: ", at);
        if (!expect(s, '=') || !expression(s, "", st)) return false;
        out.add(std::move(st));
        return true;
    }

    // #define name value;
    bool define(Scanner& s, size_t at) {
        Statement st = out.start(at);
        st.emit("#define ", at);
        s.skipSpaces();
        size_t nameAt = s.pos;
        std::string_view name = s.identifier();
        if (name.empty()) return fail(s.pos, "missing constant name", "a name");
        st.copy(name, nameAt);
        st.emit(" ", s.pos);
        if (!expression(s, "", st)) return false;
        out.add(std::move(st));
        return true;
    }

    // #object F BRANCH;  kept as a comment: objects mean nothing to rewriting.
    bool object(Scanner& s, size_t at) {
        s.skipSpaces();
        size_t moduleAt = s.pos;
        std::string_view module = moduleName(s);
        s.skipSpaces();
        size_t objectAt = s.pos;
        std::string_view object = s.identifier();
        if (module.empty() || object.empty())
            return fail(module.empty() ? moduleAt : objectAt, "malformed #object", "'#object MODULE OBJECT;'");
        Statement st = out.start(at);
        st.emit("// object ", at), st.copy(module, moduleAt), st.emit(": ", at), st.copy(object, objectAt);
        out.add(std::move(st));
        return true;
    }

    // #w : modules;
    bool axiom(Scanner& s, size_t at) {
        Statement st = out.start(at);
        st.emit("Axiom: ", at);
        if (!expect(s, ':') || !modules(s, st, false)) return false;
        out.add(std::move(st));
        return true;
    }

    // #label : predecessor : condition : successor;
    bool production(Scanner& s, size_t at, std::string_view label) {
        Statement st = out.start(at), predecessor, condition, successor;
        if (!expect(s, ':') || !modules(s, predecessor, true, &condition) || !expect(s, ':')) return false;
        s.skipSpaces();
        std::optional<Statement> probability;
        size_t conditionAt = s.pos;
        if (s.accept("~")) {
            probability.emplace();
            if (!expression(s, ":", *probability)) return false;
        } else if (s.accept("*")) {
            // no condition
        } else {
            Statement written;
            if (!expression(s, ":", written)) return false;
            if (!condition.text.empty()) condition.emit(" && ", conditionAt);
            condition.emit("(", conditionAt), condition.append(written), condition.emit(")", conditionAt);
        }
        if (!expect(s, ':') || !modules(s, successor, false)) return false;
        // A label the native parser would read as a module name is dropped.
        if (label.size() >= 2 && !names.multiLetter.contains(std::string(label)))
            st.copy(label, at + 1), st.emit(": ", at);
        st.append(predecessor);
        if (!condition.text.empty()) st.emit(" : ", conditionAt), st.append(condition);
        st.emit(" --> ", conditionAt), st.append(successor);
        if (probability) st.emit(" : ", conditionAt), st.append(*probability);
        out.add(std::move(st));
        return true;
    }

    bool statement(Scanner& s) {
        size_t at = s.pos;
        if (!s.accept("#"))
            return fail(at, std::string("unexpected '") + s.peek() + "'", "a statement starting with '#'");
        std::string_view keyword = s.identifier();
        bool ok = keyword == "n"        ? generations(s, at)
                  : keyword == "define" ? define(s, at)
                  : keyword == "object" ? object(s, at)
                  : keyword == "w"      ? axiom(s, at)
                  : !keyword.empty()    ? production(s, at, keyword)
                                        : fail(s.pos, "missing statement name after '#'",
                                               "'n', 'define', 'object', 'w' or a production label such as 'p1'");
        return ok && expect(s, ';');
    }

    Translation run() {
        Scanner s{source};
        while (true) {
            s.skipWhitespace();
            if (s.atEnd()) break;
            if (!statement(s)) { // resume after the next ';' of this line
                while (!s.atLineEnd() && s.peek() != ';') ++s.pos;
                s.accept(";");
            }
        }
        names.declare(out);
        for (std::string_view line : {"interpretation:", "F(l,k) --> @K(k) F(l)", "!(w,r) --> !(w)"}) {
            Statement st = out.start(source.text.size());
            st.emit(line, source.text.size());
            out.addLast(std::move(st));
        }
        return out.finish(std::move(diagnostics));
    }
};

} // namespace

Translation translateCrankshaw(const Source& source) { return Crankshaw{source}.run(); }

} // namespace lsys
