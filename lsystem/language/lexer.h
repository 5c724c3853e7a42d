#pragma once
// Character-level scanning shared by the .lsys parser and the expression
// compiler. Sources are handled one line at a time (after comments are blanked
// out), so an error never costs more than the rest of its line.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/common/error.h"

namespace lsys {

// Replaces /* */ and // comments with spaces, keeping every newline and column,
// so diagnostics still point into the original text.
std::string blankComments(std::string_view source, const std::string& file, std::vector<Diagnostic>& diagnostics);

// Splits text into lines (without the terminators, a trailing \r removed).
std::vector<std::string_view> splitLines(std::string_view text);

struct Cursor {
    std::string_view text; // one source line
    size_t pos = 0;
    int line = 1;

    bool atEnd() const { return pos >= text.size(); }
    char peek(size_t ahead = 0) const { return pos + ahead < text.size() ? text[pos + ahead] : '\0'; }
    int column() const { return static_cast<int>(pos) + 1; }
    void skipSpaces();
    // Consumes literal if the text continues with it.
    bool accept(std::string_view literal);
    bool startsWith(std::string_view literal) const { return text.substr(pos).starts_with(literal); }
    // [A-Za-z_][A-Za-z0-9_]*, or empty when none starts here.
    std::string_view identifier();
    // True at "->" or "-->", which end a predecessor or condition.
    bool atArrow() const { return startsWith("->") || startsWith("-->"); }
};

bool isIdentifierStart(char c);
bool isIdentifierChar(char c);

// Builds a diagnostic at the cursor's current position.
Diagnostic errorAt(const Cursor& cursor, const std::string& file, std::string message, std::string expected = {});

// Where a line-by-line reader of a file reports its errors (the vlab
// object's function and surface files).
struct ErrorReport {
    std::string file;
    std::vector<Diagnostic>& diagnostics;

    // Appends an error at the cursor; false, for `return fail(...)`.
    bool fail(const Cursor& at, std::string message, std::string expected) const {
        diagnostics.push_back(errorAt(at, file, std::move(message), std::move(expected)));
        return false;
    }
    std::nullopt_t failed(const Cursor& at, std::string message, std::string expected) const {
        fail(at, std::move(message), std::move(expected));
        return std::nullopt;
    }
};

} // namespace lsys
