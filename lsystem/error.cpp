#include "lsystem/error.h"

#include <algorithm>

namespace lsys {

namespace {

std::string_view lineOf(std::string_view source, int line) {
    size_t begin = 0;
    for (int current = 1; current < line; ++current) {
        size_t newline = source.find('\n', begin);
        if (newline == std::string_view::npos) return {};
        begin = newline + 1;
    }
    size_t end = source.find('\n', begin);
    if (end == std::string_view::npos) end = source.size();
    std::string_view text = source.substr(begin, end - begin);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
}

} // namespace

std::string formatDiagnostic(const Diagnostic& diagnostic, std::string_view source) {
    std::string out = diagnostic.file + ":" + std::to_string(diagnostic.line) + ":" +
                      std::to_string(diagnostic.column) + ": error: " + diagnostic.message;
    if (!diagnostic.expected.empty()) out += " (expected " + diagnostic.expected + ")";
    out += '\n';
    std::string_view text = lineOf(source, diagnostic.line);
    if (diagnostic.line > 0 && (!text.empty() || diagnostic.column > 0)) {
        out += "  ";
        out += text;
        out += "\n  ";
        // Keep tabs so the caret lines up under the offending character.
        for (int i = 1; i < diagnostic.column; ++i)
            out += (static_cast<size_t>(i - 1) < text.size() && text[i - 1] == '\t') ? '\t' : ' ';
        out += "^\n";
    }
    return out;
}

std::string formatDiagnostics(const std::vector<Diagnostic>& diagnostics, std::string_view source) {
    std::string out;
    for (const Diagnostic& diagnostic : diagnostics) out += formatDiagnostic(diagnostic, source);
    return out;
}

void sortBySourcePosition(std::vector<Diagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
}

} // namespace lsys
