#include "lsystem/common/error.h"

#include <algorithm>

namespace lsys {

namespace {

// Where each line of the source begins: found once, so reporting many
// diagnostics costs one pass over the source, not one pass each.
class LineIndex {
public:
    explicit LineIndex(std::string_view source) : source_(source) {
        starts_.push_back(0);
        for (size_t i = 0; i < source.size(); ++i)
            if (source[i] == '\n') starts_.push_back(i + 1);
    }

    // Line `line` (1-based) without its end of line; empty past the end.
    std::string_view line(int line) const {
        if (line < 1 || size_t(line) > starts_.size()) return {};
        const size_t begin = starts_[size_t(line) - 1];
        size_t end = size_t(line) < starts_.size() ? starts_[size_t(line)] - 1 : source_.size();
        std::string_view text = source_.substr(begin, end - begin);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        return text;
    }

private:
    std::string_view source_;
    std::vector<size_t> starts_;
};

// The part of a long line shown around the column: a 10 MB line is not
// printed whole. `column` becomes the caret's column in what is shown.
std::string_view windowAround(std::string_view text, int& column, bool& cutBefore, bool& cutAfter) {
    const size_t at = size_t(std::max(column, 1)) - 1;
    const size_t begin = at > kDiagnosticContext ? at - kDiagnosticContext : 0;
    const size_t end = std::min(text.size(), at + kDiagnosticContext);
    cutBefore = begin > 0;
    cutAfter = end < text.size();
    column = int(at - begin) + 1;
    return begin < end ? text.substr(begin, end - begin) : std::string_view();
}

std::string formatWithLine(const Diagnostic& diagnostic, std::string_view text) {
    std::string out = diagnostic.file;
    // Line 0 is the file as a whole (it cannot be read, a folder lacks it).
    if (diagnostic.line > 0)
        out.append(":").append(std::to_string(diagnostic.line)).append(":").append(std::to_string(diagnostic.column));
    out.append(diagnostic.severity == Severity::Warning ? ": warning: " : ": error: ").append(diagnostic.message);
    if (!diagnostic.expected.empty()) out += " (expected " + diagnostic.expected + ")";
    out += '\n';
    if (diagnostic.line > 0 && (!text.empty() || diagnostic.column > 0)) {
        int column = diagnostic.column;
        bool cutBefore = false, cutAfter = false;
        const std::string_view shown = windowAround(text, column, cutBefore, cutAfter);
        const std::string_view ellipsis = "...";
        out += "  ";
        if (cutBefore) out += ellipsis;
        out += shown;
        if (cutAfter) out += ellipsis;
        out += "\n  ";
        if (cutBefore) out.append(ellipsis.size(), ' ');
        // Keep tabs so the caret lines up under the offending character.
        for (int i = 1; i < column; ++i)
            out += (size_t(i - 1) < shown.size() && shown[size_t(i) - 1] == '\t') ? '\t' : ' ';
        out += "^\n";
    }
    return out;
}

} // namespace

std::string formatDiagnostic(const Diagnostic& diagnostic, std::string_view source) {
    return formatWithLine(diagnostic, diagnostic.sourceLine.empty() ? LineIndex(source).line(diagnostic.line)
                                                                    : diagnostic.sourceLine);
}

std::string formatDiagnostics(const std::vector<Diagnostic>& diagnostics, std::string_view source) {
    const LineIndex lines(source);
    std::string out;
    const size_t shown = std::min(diagnostics.size(), kMaxReportedDiagnostics);
    for (size_t i = 0; i < shown; ++i) {
        const Diagnostic& diagnostic = diagnostics[i];
        out += formatWithLine(diagnostic,
                              diagnostic.sourceLine.empty() ? lines.line(diagnostic.line) : diagnostic.sourceLine);
    }
    if (diagnostics.size() > shown)
        out += diagnostics.front().file + ": " + std::to_string(diagnostics.size() - shown) +
               " more errors not shown (" + std::to_string(diagnostics.size()) + " in all)\n";
    return out;
}

void sortBySourcePosition(std::vector<Diagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
}

} // namespace lsys
