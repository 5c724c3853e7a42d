// cpfg, the L-system reader of the vlab suite (Měch 2005, "CPFG Version 4.0
// User's Manual", §5.1), whose files mostly are native text already: the
// same headers, productions, contexts and modules. What it spells its own
// way becomes native here; the rest is copied byte for byte.
//   - A line that begins with a tab continues the statement above: cpfg's
//     lexer reads a newline followed by a tab as white space, so a long
//     production goes on over tab-indented lines.
//   - "homomorphism" and "decomposition" may have no colon, and a section
//     header may be followed by "warnings" or "no warnings" (whether cpfg
//     warns of modules no rule matches: nothing here to derive).
//   - "derivationlength:" may lack its space.
//   - A statement block ({ ... } after Start:, End:, StartEach:, EndEach:
//     or define:, or around a production's condition) may span lines: its
//     lines are joined into one native statement, as cpfg's grammar lets
//     blank lines and statements follow each other inside the braces.
//   - Expressions compute as cpfg's do, a '%' cuts its branch when the next
//     step reads it, and contexts match by cpfg's rules: "arithmetic: cpfg",
//     "cut: next step" and "context: cpfg" come first; so do "turtle
//     modules: cpfg" (cpfg's turtle's G, g and '@') and "decompose axiom:
//     no" (cpfg decomposes what each step makes, not the axiom).
// The other constructs of cpfg's language are the native parser's to
// accept or reject (docs/DIALECTS.md, "cpfg").

#include <array>
#include <cctype>

#include "lsystem/dialects/native_text.h"
#include "lsystem/language/lexer.h"

namespace lsys {

namespace {

struct Spelling {
    std::string_view cpfg;   // lower case; cpfg accepts a capital first letter too
    std::string_view native; // header written instead
    bool colonOptional;
};

constexpr std::array kSpellings = {
    Spelling{"homomorphism", "interpretation:", true},
    Spelling{"decomposition", "decomposition:", true},
    Spelling{"derivationlength", "derivation length:", false},
};

// The spelling `word` is, its first letter in either case and the rest as
// written (cpfg's lexer: "(H|h)omomorphism"); null for none.
const Spelling* spellingOf(std::string_view word) {
    for (const Spelling& spelling : kSpellings)
        if (word.size() == spelling.cpfg.size() &&
            std::tolower(static_cast<unsigned char>(word[0])) == spelling.cpfg[0] &&
            word.substr(1) == spelling.cpfg.substr(1))
            return &spelling;
    return nullptr;
}

struct Cpfg {
    const Source& source;
    NativeText out{source};

    size_t lineEnd(size_t begin) const { return std::min(source.text.find('\n', begin), source.text.size()); }

    // The line's header in cpfg's spelling as native text, the rest of the
    // line copied; false when the line starts with no such header.
    bool header(Statement& into, size_t begin, size_t end) const {
        Scanner s{source, begin};
        s.skipSpaces();
        const size_t at = s.pos;
        const Spelling* spelling = spellingOf(s.identifier());
        if (!spelling) return false;
        s.skipSpaces();
        if (!s.accept(":") && !spelling->colonOptional) return false;
        s.skipSpaces();
        if (spelling->colonOptional) { // cpfg's warnings switch: "warnings" or "no warnings"
            const size_t before = s.pos;
            if (s.identifier() == "no")
                s.skipSpaces();
            else
                s.pos = before;
            if (s.identifier() == "warnings")
                s.skipSpaces();
            else
                s.pos = before;
        }
        into.emit(spelling->native, at);
        into.emit(" ", s.pos);
        into.copy(std::string_view(source.text).substr(s.pos, end - s.pos), s.pos);
        return true;
    }

    // How many statement blocks the statement so far leaves open: braces
    // count on a global block's line (Start:, define:, ...), and in a
    // production between the condition's ':' and the arrow; elsewhere they
    // are polygon modules.
    static int openBlocks(std::string_view text) {
        size_t at = text.find_first_not_of(" \t");
        std::string word;
        while (at < text.size() && isIdentifierChar(text[at]))
            word += static_cast<char>(std::tolower(static_cast<unsigned char>(text[at++])));
        size_t begin = 0, end = text.size();
        if (word != "start" && word != "end" && word != "starteach" && word != "endeach" && word != "define") {
            const size_t arrow = std::min(text.find("->"), text.size());
            begin = text.find(':');
            if (begin >= arrow) return 0;
            end = arrow;
        }
        int depth = 0;
        for (size_t i = begin; i < end; ++i) depth += text[i] == '{' ? 1 : text[i] == '}' ? -1 : 0;
        return depth;
    }

    Translation run() {
        const std::string& text = source.text;
        for (std::string_view setting :
             {"arithmetic: cpfg", "cut: next step", "context: cpfg", "turtle modules: cpfg", "decompose axiom: no"}) {
            Statement header = out.start(0);
            header.emit(setting, 0);
            out.addFirst(std::move(header));
        }
        for (size_t begin = 0; begin < text.size();) {
            Statement statement = out.start(begin);
            size_t end = lineEnd(begin);
            if (!header(statement, begin, end))
                statement.copy(std::string_view(text).substr(begin, end - begin), begin);
            // The statement goes on over tab-indented lines and to the end of an open block.
            while (end + 1 < text.size() && (text[end + 1] == '\t' || openBlocks(statement.text) > 0)) {
                statement.emit(" ", end);
                const size_t next = end + 1;
                end = lineEnd(next);
                statement.copy(std::string_view(text).substr(next, end - next), next);
            }
            out.add(std::move(statement));
            begin = end + 1;
        }
        return out.finish({});
    }
};

} // namespace

Translation translateCpfg(const Source& source) { return Cpfg{source}.run(); }

std::vector<Diagnostic> cpfgCommentWarnings(std::string_view source, const std::string& file) {
    std::vector<Diagnostic> warnings;
    int line = 1;
    bool inBlockComment = false;
    for (size_t begin = 0; begin <= source.size(); ++line) {
        const size_t end = std::min(source.find('\n', begin), source.size());
        const std::string_view text = source.substr(begin, end - begin);
        const size_t arrow = text.find("->");
        for (size_t i = 0; i + 1 < text.size(); ++i) {
            if (inBlockComment) {
                if (text.substr(i, 2) == "*/") inBlockComment = false, ++i;
                continue;
            }
            if (text.substr(i, 2) == "/*") {
                inBlockComment = true;
                ++i;
                continue;
            }
            if (text.substr(i, 2) != "//") continue;
            if (arrow != std::string_view::npos && arrow < i && i > 0 && text[i - 1] != ' ' && text[i - 1] != '\t')
                warnings.push_back({file,
                                    line,
                                    static_cast<int>(i) + 1,
                                    "'//' starts a comment here, as in cpfg: the rest of the line is not part of the "
                                    "production (write '/ /' for two rolls)",
                                    {},
                                    {},
                                    Severity::Warning});
            break; // the rest of the line is a comment
        }
        begin = end + 1;
    }
    return warnings;
}

} // namespace lsys
