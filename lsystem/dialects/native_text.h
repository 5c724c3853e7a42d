#pragma once
// Shared by the dialect translators: the dialect source as they scan it, and
// the native text they build, statement by statement, remembering for every
// byte where in the dialect source it came from.

#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/dialects/dialect.h"

namespace lsys {

// The original text with comments and the dialect header line blanked out
// (same length, so offsets and columns stay those of the original).
struct Source {
    std::string file;
    std::string text;
    std::vector<size_t> lineStarts;

    Source(std::string_view original, std::string file, std::vector<Diagnostic>& diagnostics);
    int lineOf(size_t offset) const;
    Diagnostic diagnostic(size_t offset, std::string message, std::string expected = {}) const;
};

// A cursor over Source::text. Scanning never passes the end of the text.
struct Scanner {
    const Source& source;
    size_t pos = 0;

    bool atEnd() const { return pos >= source.text.size(); }
    char peek(size_t ahead = 0) const;
    bool accept(std::string_view literal);
    void skipSpaces();     // spaces and tabs, not newlines
    void skipWhitespace(); // newlines too
    bool atLineEnd() const { return atEnd() || peek() == '\n' || peek() == '\r'; }
    std::string_view identifier(); // [A-Za-z_][A-Za-z0-9_]*, or empty
    std::string_view number();     // unsigned decimal with optional fraction and exponent, or empty
};

// One native line: its text, the source offset of each of its bytes, and the
// line it should land on (that of its dialect statement).
struct Statement {
    std::string text;
    std::vector<uint32_t> origin;
    int preferredLine = 1;

    void copy(std::string_view piece, size_t sourceOffset); // byte i comes from sourceOffset + i
    void emit(std::string_view piece, size_t sourceOffset); // generated text standing for sourceOffset
    void append(const Statement& other);
};

class NativeText {
public:
    explicit NativeText(const Source& source) : source_(source) {}

    // An empty statement for the dialect text at sourceOffset, to fill and add.
    Statement start(size_t sourceOffset) const;
    void add(Statement statement) { body_.push_back(std::move(statement)); }
    void addFirst(Statement statement) { leading_.push_back(std::move(statement)); } // before all others (declarations)
    void addLast(Statement statement) {
        trailing_.push_back(std::move(statement));
    } // after all others (appended sections)

    // Lays statements out on their preferred lines where free, otherwise on
    // the next free line, keeping their order.
    Translation finish(std::vector<Diagnostic> diagnostics) const;

private:
    const Source& source_;
    std::vector<Statement> leading_, body_, trailing_;
};

// Multi-letter module names, which native text must declare with 'module'.
struct ModuleNames {
    std::set<std::string> multiLetter;
    size_t firstUse = 0;

    void use(std::string_view name, size_t sourceOffset);
    // "module a, b" as a leading statement, when any name was used.
    void declare(NativeText& out) const;
};

// Shortest text that reads back as the same double.
std::string formatNumber(double value);

// The byte range [begin, end) of the dialect header line, if the source has one.
struct HeaderLine {
    size_t begin = 0, end = 0;
    Dialect dialect = Dialect::Native;
};
std::optional<HeaderLine> findHeaderLine(std::string_view source);

// The translators, one per dialect file.
Translation translateCrankshaw(const Source& source);
Translation translateRobbins(const Source& source);
Translation translatePlantlang(const Source& source);
Translation translateCpfg(const Source& source);

// cpfg's preprocessor takes "//" for a comment wherever it stands, which
// silently cuts ABOP's roll runs ("F/////F" is "F/"): a warning at each "//"
// that follows a module on a production's line.
std::vector<Diagnostic> cpfgCommentWarnings(std::string_view source, const std::string& file);

} // namespace lsys
