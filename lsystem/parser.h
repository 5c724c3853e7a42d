#pragma once
// Reads the native .lsys notation (DESIGN.md §2, docs/LSYS_FORMAT.md) into a Grammar.

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lsystem/dialect.h"
#include "lsystem/error.h"
#include "lsystem/grammar.h"

namespace lsys {

struct ParseOptions {
    std::string file = "<input>";                     // name used in diagnostics
    std::unordered_map<std::string, double> defines;  // override (or add) #define constants
    std::optional<Dialect> dialect;                   // default: the file's "dialect:" line, else native
};

struct ParseResult {
    Grammar grammar;
    std::vector<Diagnostic> diagnostics;  // every problem found, in source order
    bool ok() const { return diagnostics.empty(); }
};

// Never throws on malformed input and never recurses deeper than a fixed bound.
// Files in another notation are translated first (lsystem/dialect.h).
ParseResult parseLsystem(std::string_view source, const ParseOptions& options = {});

// Reads a file; a missing file becomes a diagnostic at line 0.
ParseResult loadLsystemFile(const std::string& path, ParseOptions options = {});
std::string readTextFile(const std::string& path, bool& ok);

}  // namespace lsys
