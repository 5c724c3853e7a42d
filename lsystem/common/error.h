#pragma once
// Diagnostics for malformed input and errors raised while deriving.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lsys {

// One problem found in a source file. Lines and columns are 1-based.
enum class Severity : uint8_t { Error, Warning };

struct Diagnostic {
    std::string file;
    int line = 0;
    int column = 0;
    std::string message;  // what is wrong
    std::string expected; // what would have been accepted here (may be empty)
    // The offending line when it is not in the source the diagnostics are
    // formatted with (a line of an #include'd file); empty otherwise.
    std::string sourceLine;
    Severity severity = Severity::Error; // a warning leaves the file readable
};

// Characters of the offending line shown either side of the column; a
// longer line is cut with "..." marks.
inline constexpr size_t kDiagnosticContext = 80;
// formatDiagnostics reports this many and counts the rest, as compilers do.
inline constexpr size_t kMaxReportedDiagnostics = 100;

// "file:line:col: error: message (expected ...)" followed by the offending
// source line (or kDiagnosticContext characters either side of the column)
// and a caret under the column.
std::string formatDiagnostic(const Diagnostic& diagnostic, std::string_view source);
// The first kMaxReportedDiagnostics, then a line counting the others.
std::string formatDiagnostics(const std::vector<Diagnostic>& diagnostics, std::string_view source);

// Orders diagnostics by line, then column, keeping the order of equal positions.
void sortBySourcePosition(std::vector<Diagnostic>& diagnostics);

// Raised by derivation and interpretation: budget exceeded, bad runtime value.
struct DerivationError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The derivation would outgrow DeriveOptions::maxModules (or memory first).
// Its own type so each tool can name its own way to raise the budget or
// derive less.
struct ModuleBudgetError : DerivationError {
    using DerivationError::DerivationError;
};

} // namespace lsys
