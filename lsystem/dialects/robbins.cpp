// Robbins 1998 (Branching Shadows): a free-form stream of words.
//   iterations 10 angle 30 length 1 thickness .2 startpoint 0 0 0 forward 0 0 1 left 1 0 0 up 0 1 0
//   FP A                                   the axiom: every module before the first production
//   A --> !(.9) t(.1) FP B >(94) B         a production runs until the next "NAME -->"
// Modules are names ([A-Za-z_][A-Za-z0-9_]*, multi-letter ones declared with
// 'module') and one-character turtle symbols, each with an optional (value).
// Robbins' own symbols become native ones (table below); his turtle starts
// from startpoint/forward/left/up, which are kept as comments only.

#include <array>

#include "lsystem/dialects/native_text.h"
#include "lsystem/language/lexer.h"

namespace lsys {

namespace {

struct SymbolRule {
    std::string_view robbins;
    std::string_view bare;      // native text for the module without a value
    std::string_view withValue; // native name taking the value; empty: no value allowed
};

constexpr std::array kRules = {
    SymbolRule{"+", "+", "+"},
    SymbolRule{"-", "-", "-"},
    SymbolRule{"&", "&", "&"},
    SymbolRule{"^", "^", "^"},
    SymbolRule{"<", "\\", "\\"},
    SymbolRule{">", "/", "/"},
    SymbolRule{"|", "|", ""},
    SymbolRule{"%", "/(180)", ""},
    SymbolRule{"$", "$", ""},
    SymbolRule{"[", "[", ""},
    SymbolRule{"]", "]", ""},
    SymbolRule{"{", "[ {", ""},
    SymbolRule{"}", "} ]", ""}, // a polygon saves and restores the turtle
    SymbolRule{"\"", "@Lm(1.1)", "@Lm"},
    SymbolRule{"'", "@Lm(0.9)", "@Lm"},
    SymbolRule{";", "@Am(1.1)", "@Am"},
    SymbolRule{":", "@Am(0.9)", "@Am"},
    SymbolRule{"?", "@Wm(1.4)", "@Wm"},
    SymbolRule{"!", "@Wm(0.7)", "@Wm"},
    SymbolRule{"t", "@Ts(0.2)", "@Ts"}, // gravity
};

struct RobbinsSetting {
    std::string_view keyword;
    int values;
    std::string_view native; // header written with the value; empty: kept as a comment
};

constexpr std::array kRobbinsSettings = {
    RobbinsSetting{"iterations", 1, "derivation length: "},
    RobbinsSetting{"angle", 1, "angle: "},
    RobbinsSetting{"length", 1, "step: "},
    RobbinsSetting{"thickness", 1, "width: "},
    RobbinsSetting{"startpoint", 3, ""},
    RobbinsSetting{"forward", 3, ""},
    RobbinsSetting{"left", 3, ""},
    RobbinsSetting{"up", 3, ""},
};

struct Robbins {
    const Source& source;
    NativeText out{source};
    ModuleNames names;
    std::vector<Diagnostic> diagnostics;

    void fail(size_t offset, std::string message, std::string expected = {}) {
        diagnostics.push_back(source.diagnostic(offset, std::move(message), std::move(expected)));
    }

    // "NAME -->" starts at the scanner (after whitespace)?
    bool atProduction(Scanner s) const {
        s.skipWhitespace();
        if (s.identifier().empty()) return false;
        s.skipWhitespace();
        return s.accept("-->");
    }

    // A signed number of the header; empty when none.
    std::string_view headerNumber(Scanner& s) {
        s.skipWhitespace();
        size_t begin = s.pos;
        s.accept("-");
        if (s.number().empty()) {
            s.pos = begin;
            return {};
        }
        return std::string_view(source.text).substr(begin, s.pos - begin);
    }

    void header(Scanner& s) {
        while (true) {
            Scanner look = s;
            look.skipWhitespace();
            size_t at = look.pos;
            std::string_view word = look.identifier();
            const RobbinsSetting* setting = nullptr;
            for (const RobbinsSetting& candidate : kRobbinsSettings)
                if (candidate.keyword == word) setting = &candidate;
            if (!setting || atProduction(s)) return;
            s.pos = look.pos;
            Statement st = out.start(at);
            st.emit(setting->native.empty() ? "// " : setting->native, at);
            if (setting->native.empty()) st.copy(word, at);
            for (int i = 0; i < setting->values; ++i) {
                std::string_view value = headerNumber(s);
                if (value.empty()) return fail(s.pos, std::string("missing value of '").append(word) + "'", "a number");
                if (setting->native.empty()) st.emit(" ", at);
                st.copy(value, s.pos - value.size());
            }
            if (setting->native.empty()) st.emit(" (turtle start, not used)", at);
            out.add(std::move(st));
        }
    }

    // "(...)" after a module, copied for the native expression parser; false on error.
    bool value(Scanner& s, Statement& into) {
        size_t open = s.pos;
        int depth = 0;
        do {
            if (s.atLineEnd()) {
                fail(open, "unclosed '('", "')' on the same line");
                return false;
            }
            depth += s.peek() == '(' ? 1 : s.peek() == ')' ? -1 : 0;
            ++s.pos;
        } while (depth > 0);
        into.copy(std::string_view(source.text).substr(open, s.pos - open), open);
        return true;
    }

    // One module at the scanner, appended to into; false on error.
    bool module(Scanner& s, Statement& into) {
        size_t at = s.pos;
        std::string_view name = s.identifier();
        if (name.empty() && !s.atEnd()) name = std::string_view(source.text).substr(s.pos++, 1);
        const SymbolRule* rule = nullptr;
        for (const SymbolRule& candidate : kRules)
            if (candidate.robbins == name) rule = &candidate;
        bool hasValue = s.peek() == '(';
        if (!rule && !isIdentifierStart(name[0])) {
            fail(at, std::string("unknown symbol '").append(name) + "'",
                 "a name or one of + - & ^ < > | % $ [ ] { } \" ' ; : ? ! t");
            return false;
        }
        if (!into.text.empty()) into.emit(" ", at);
        if (!rule) {
            names.use(name, at);
            into.copy(name, at);
        } else if (!hasValue) {
            into.emit(rule->bare, at);
        } else if (rule->withValue.empty()) {
            fail(s.pos, std::string("'").append(name) + "' takes no value");
            return false;
        } else {
            into.emit(rule->withValue, at);
        }
        return !hasValue || value(s, into);
    }

    // Modules until the next production or the end; false on error.
    bool modules(Scanner& s, Statement& into) {
        while (true) {
            s.skipWhitespace();
            if (s.atEnd() || atProduction(s)) return true;
            if (size_t at = s.pos; s.accept("-->")) { // read as the symbols - - > it would hide a typo
                fail(at, "'-->' without a production name", "NAME --> successor");
                return false;
            }
            if (!module(s, into)) return false;
        }
    }

    // Skips to the next production after an error, a word at a time (linear in the text).
    void recover(Scanner& s) {
        while (true) {
            s.skipWhitespace();
            if (s.atEnd() || atProduction(s)) return;
            if (s.identifier().empty()) ++s.pos;
        }
    }

    Translation run() {
        Scanner s{source};
        header(s);
        s.skipWhitespace();
        if (!s.atEnd() && !atProduction(s)) {
            Statement st = out.start(s.pos);
            st.emit("Axiom:", s.pos);
            if (modules(s, st))
                out.add(std::move(st));
            else
                recover(s);
        }
        while (true) {
            s.skipWhitespace();
            if (s.atEnd()) break;
            size_t at = s.pos;
            std::string_view name = s.identifier();
            names.use(name, at);
            s.skipWhitespace();
            s.accept("-->");
            Statement st = out.start(at);
            st.copy(name, at);
            st.emit(" --> ", at);
            Statement successor;
            if (modules(s, successor)) {
                st.append(successor);
                out.add(std::move(st));
            } else {
                recover(s);
            }
        }
        names.declare(out);
        return out.finish(std::move(diagnostics));
    }
};

} // namespace

Translation translateRobbins(const Source& source) { return Robbins{source}.run(); }

} // namespace lsys
