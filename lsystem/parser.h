#pragma once
// Reads the native .lsys notation (docs/LSYS_FORMAT.md) into a Grammar.

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lsystem/error.h"
#include "lsystem/grammar.h"

namespace lsys {

struct ParseOptions {
    std::string file = "<input>";                    // name used in diagnostics
    std::unordered_map<std::string, double> defines; // override (or add) #define constants
};

struct ParseResult {
    Grammar grammar;
    std::vector<Diagnostic> diagnostics; // every problem found, in source order
    bool ok() const { return diagnostics.empty(); }
};

// Reads native text only. Never throws on malformed input and never recurses
// deeper than a fixed bound. Plant files, whatever their notation, are read
// through parseDialect / loadDialectFile (lsystem/dialects/dialect.h), which
// translate other notations and call this.
ParseResult parseLsystem(std::string_view source, const ParseOptions& options = {});

std::string readTextFile(const std::string& path, bool& ok);

} // namespace lsys
