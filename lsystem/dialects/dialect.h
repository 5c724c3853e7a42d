#pragma once
// The notations of the source documents and of vlab's cpfg (docs/DIALECTS.md),
// each read by translating it into native .lsys text, which the native parser
// then reads: every dialect ends in the same Grammar.
//   crankshaw  Crankshaw 2020: #n = 6; #define r 20; #w : ...; #p1 : pred : cond : succ;
//   robbins    Robbins 1998: iterations 10 angle 30 ...  A --> ...
//   plantlang  the clouds-and-mountains chapter:
//              Axiom = f20t15dX   X => t<dY   d m f u r t T o O c a A l L
//   cpfg       vlab's cpfg (.l files): native text in cpfg's spellings
// (Dialect and the names, lsystem/language/dialect_names.h.)

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/common/error.h"
#include "lsystem/language/dialect_names.h"
#include "lsystem/language/parser.h"

namespace lsys {

// The first non-blank line "dialect: NAME" (also "// dialect: NAME",
// "/* dialect: NAME */", "# dialect: NAME") selects the dialect; Native otherwise.
Dialect detectDialect(std::string_view source);

struct Translation {
    std::string nativeSource;
    std::vector<Diagnostic> diagnostics; // dialect-level problems, at positions of the original source
    // Per byte of nativeSource, the byte of the original source it came from.
    // Native line N holds what dialect line N said wherever the dialect puts one
    // statement per line; mapToSource() maps the rest.
    std::vector<uint32_t> origin;
};

Translation translateToNative(Dialect dialect, std::string_view source, const std::string& file);

// Moves diagnostics about translation.nativeSource to the lines and columns
// of the original source the offending text came from.
void mapToSource(const Translation& translation, std::string_view source, std::vector<Diagnostic>& diagnostics);

// The entry point for plant text in any notation: the given dialect, else the
// one the header line names, else native. Translates, parses the native text
// and reports every diagnostic (dialect and native) at its position in the
// original source, in source order.
ParseResult parseDialect(std::optional<Dialect> dialect, std::string_view source, const ParseOptions& options = {});

// The dialect a file is read in: `given`, else its header line's, else cpfg
// for a name ending in ".l" (cpfg's own extension), else native.
Dialect dialectOfFile(std::optional<Dialect> given, std::string_view source, std::string_view path);

// Reads a file and parses it with parseDialect in dialectOfFile's dialect; a
// missing file becomes a diagnostic at line 0.
ParseResult loadDialectFile(const std::string& path, std::optional<Dialect> dialect = std::nullopt,
                            ParseOptions options = {});

} // namespace lsys
