#pragma once
// cpfg reads every L-system through a C preprocessor (vlab's vlabcpp, GNU's
// cccp of the 1990s: #define, function-like macros, #if, #include, and the
// removal of /* */ and // comments) before its own lexer sees it (Měch 2005,
// "CPFG Version 4.0 User's Manual", §5.1). This runs the system's `cpp` the
// same way and keeps, for every line of its output, the file and line it came
// from, so that later diagnostics point into the user's files.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/common/error.h"

namespace lsys {

struct PreprocessOptions {
    std::string program = "cpp";
    std::vector<std::string> includeDirectories; // searched by #include, in order
    // Object-like macros set from outside (lsys -D): a #define of the same
    // name in the main file is replaced by this value, otherwise it is added.
    std::vector<std::pair<std::string, std::string>> macros;
};

struct PreprocessedText {
    struct Origin {
        uint32_t file = 0; // index into files
        int line = 0;      // 1-based line of that file
    };
    std::string text;                    // the preprocessor's output without its line markers
    std::vector<Origin> lines;           // one per line of text
    std::vector<std::string> files;      // files[0] is the main file, as diagnostics name it
    std::vector<std::string> fileTexts;  // each file's text, for columns and quoted lines
    std::vector<Diagnostic> diagnostics; // the preprocessor's own errors, in the user's files
    std::vector<Diagnostic> warnings;    // lines cpfg's preprocessor complains of but passes on
};

// Preprocesses `source`, the text of `file`. A line that began with a tab
// (cpfg's continuation of the statement above) still begins with one: the
// preprocessor writes leading white space as spaces.
PreprocessedText runCPreprocessor(std::string_view source, const std::string& file, const PreprocessOptions& options);

// Moves diagnostics at lines and columns of `preprocessed.text` to the files,
// lines and columns their text came from. A diagnostic in an #include'd file
// carries that file's line in Diagnostic::sourceLine.
void mapToFiles(const PreprocessedText& preprocessed, std::vector<Diagnostic>& diagnostics);

} // namespace lsys
