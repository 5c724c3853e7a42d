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
// The other constructs of cpfg's language are the native parser's to
// accept or reject (docs/DIALECTS.md, "cpfg").

#include <array>
#include <cctype>

#include "lsystem/dialects/native_text.h"

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

// `word` at `pos` of `text`, its first letter in either case and the rest
// as written, not followed by a letter or digit; the end of it, or npos.
size_t acceptWord(std::string_view text, size_t pos, std::string_view word) {
    if (text.size() - std::min(pos, text.size()) < word.size()) return std::string_view::npos;
    if (std::tolower(static_cast<unsigned char>(text[pos])) != word[0] ||
        text.substr(pos + 1, word.size() - 1) != word.substr(1))
        return std::string_view::npos;
    size_t end = pos + word.size();
    if (end < text.size() && std::isalnum(static_cast<unsigned char>(text[end]))) return std::string_view::npos;
    return end;
}

size_t skipBlanks(std::string_view text, size_t pos) {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\r')) ++pos;
    return pos;
}

struct Cpfg {
    const Source& source;
    NativeText out{source};

    size_t lineEnd(size_t begin) const { return std::min(source.text.find('\n', begin), source.text.size()); }

    // The line's header in cpfg's spelling as native text, the rest of the
    // line copied; false when the line starts with no such header.
    bool header(Statement& into, size_t begin, size_t end) const {
        const std::string_view text = std::string_view(source.text).substr(0, end);
        const size_t at = skipBlanks(text, begin);
        for (const Spelling& spelling : kSpellings) {
            size_t pos = acceptWord(text, at, spelling.cpfg);
            if (pos == std::string_view::npos) continue;
            pos = skipBlanks(text, pos);
            if (pos < text.size() && text[pos] == ':')
                pos = skipBlanks(text, pos + 1);
            else if (!spelling.colonOptional)
                continue;
            if (spelling.colonOptional) { // cpfg's warnings switch
                size_t no = acceptWord(text, pos, "no");
                size_t warnings =
                    acceptWord(text, no == std::string_view::npos ? pos : skipBlanks(text, no), "warnings");
                if (warnings != std::string_view::npos) pos = skipBlanks(text, warnings);
            }
            into.emit(spelling.native, at);
            into.emit(" ", pos);
            into.copy(text.substr(pos), pos);
            return true;
        }
        return false;
    }

    Translation run() {
        const std::string& text = source.text;
        for (size_t begin = 0; begin < text.size();) {
            Statement statement = out.start(begin);
            size_t end = lineEnd(begin);
            if (!header(statement, begin, end))
                statement.copy(std::string_view(text).substr(begin, end - begin), begin);
            while (end + 1 < text.size() && text[end + 1] == '\t') { // the statement goes on
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

} // namespace lsys
