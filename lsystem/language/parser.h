#pragma once
// Reads the native .lsys notation (docs/LSYS_FORMAT.md) into a Grammar.

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lsystem/common/error.h"
#include "lsystem/language/expression.h"
#include "lsystem/language/grammar.h"

namespace lsys {

struct ParseOptions {
    std::string file = "<input>";                    // name used in diagnostics
    std::unordered_map<std::string, double> defines; // override (or add) #define constants
    // What cpfg's func(id, x) reads: a vlab object's function files, in the
    // order its view file names them. Without (or with none), func is an error.
    FunctionTable functions;
};

struct ParseResult {
    Grammar grammar;
    std::vector<Diagnostic> diagnostics; // every problem found, in source order
    std::vector<Diagnostic> warnings;    // what may not mean what it says, though the file reads (Severity::Warning)
    bool ok() const { return diagnostics.empty(); }
};

// Reads native text only. Never throws on malformed input and never recurses
// deeper than a fixed bound. Plant files, whatever their notation, are read
// through parseDialect / loadDialectFile (lsystem/dialects/dialect.h), which
// translate other notations and call this.
ParseResult parseLsystem(std::string_view source, const ParseOptions& options = {});

// Plant files are text of at most this many bytes: a 64 MiB L-system is
// already far past any in the literature, and a device such as /dev/zero
// would otherwise be read without end.
inline constexpr size_t kMaxSourceBytes = size_t(64) << 20;
// The file's bytes; on failure empty, with `problem` saying why ("is a
// folder", "cannot be opened", "is larger than 64 MiB").
std::string readTextFile(const std::string& path, std::string& problem);

} // namespace lsys
