#include "lsystem/dialects/dialect.h"

#include <algorithm>
#include <numeric>
#include <tuple>

#include "lsystem/dialects/c_preprocessor.h"
#include "lsystem/dialects/native_text.h"

namespace lsys {

namespace {

// Native text needs no translation; only a header line the native parser would reject is blanked.
Translation blankHeader(std::string_view source) {
    Translation out;
    out.nativeSource = source;
    if (std::optional<HeaderLine> header = findHeaderLine(source))
        std::fill(out.nativeSource.begin() + header->begin, out.nativeSource.begin() + header->end, ' ');
    out.origin.resize(source.size());
    std::iota(out.origin.begin(), out.origin.end(), 0u);
    return out;
}

std::vector<size_t> lineStarts(std::string_view text) {
    std::vector<size_t> starts{0};
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') starts.push_back(i + 1);
    return starts;
}

} // namespace

Dialect detectDialect(std::string_view source) {
    std::optional<HeaderLine> header = findHeaderLine(source);
    return header ? header->dialect : Dialect::Native;
}

Translation translateToNative(Dialect dialect, std::string_view source, const std::string& file) {
    if (dialect == Dialect::Native) return blankHeader(source);
    std::vector<Diagnostic> commentProblems;
    Source text(source, file, commentProblems);
    Translation out = dialect == Dialect::Crankshaw ? translateCrankshaw(text)
                      : dialect == Dialect::Robbins ? translateRobbins(text)
                      : dialect == Dialect::Cpfg    ? translateCpfg(text)
                                                    : translatePlantlang(text);
    out.diagnostics.insert(out.diagnostics.begin(), commentProblems.begin(), commentProblems.end());
    return out;
}

void mapToSource(const Translation& translation, std::string_view source, std::vector<Diagnostic>& diagnostics) {
    if (translation.origin.empty() || diagnostics.empty()) return;
    // Both texts' line starts once for all diagnostics (a file of many
    // errors is not scanned once per error).
    const std::vector<size_t> nativeLines = lineStarts(translation.nativeSource);
    const std::vector<size_t> sourceLines = lineStarts(source);
    for (Diagnostic& diagnostic : diagnostics) {
        if (diagnostic.line < 1 || static_cast<size_t>(diagnostic.line) > nativeLines.size()) continue;
        size_t offset = nativeLines[diagnostic.line - 1] + static_cast<size_t>(std::max(diagnostic.column, 1)) - 1;
        size_t from = translation.origin[std::min(offset, translation.origin.size() - 1)];
        size_t line = std::upper_bound(sourceLines.begin(), sourceLines.end(), from) - sourceLines.begin();
        diagnostic.line = static_cast<int>(line);
        diagnostic.column = static_cast<int>(from - sourceLines[line - 1]) + 1;
    }
}

namespace {

// Translates `source`, parses the native text and reports every diagnostic
// at its position in `source`, in source order.
ParseResult parseTranslated(Dialect dialect, std::string_view source, const ParseOptions& options) {
    Translation translation = translateToNative(dialect, source, options.file);
    ParseResult result = parseLsystem(translation.nativeSource, options);
    mapToSource(translation, source, result.diagnostics);
    // A statement the translation rejected may be the axiom: "no axiom" would only repeat that error.
    if (!translation.diagnostics.empty())
        std::erase_if(result.diagnostics,
                      [](const Diagnostic& diagnostic) { return diagnostic.message == "no axiom"; });
    result.diagnostics.insert(result.diagnostics.end(), translation.diagnostics.begin(), translation.diagnostics.end());
    sortBySourcePosition(result.diagnostics);
    mapToSource(translation, source, result.warnings);
    return result;
}

// cpfg's way: the C preprocessor first, then cpfg's notation. `lsys -D`
// values become macros, as cpfg's own command-line definitions do. A file
// the preprocessor rejects is reported with its errors only, as a compiler
// stops after them.
ParseResult parseCpfg(std::string_view source, const ParseOptions& options) {
    PreprocessOptions preprocess;
    for (const auto& [name, value] : options.defines) preprocess.macros.emplace_back(name, formatNumber(value));
    std::sort(preprocess.macros.begin(), preprocess.macros.end());
    std::string text(source);
    if (std::optional<HeaderLine> header = findHeaderLine(text)) // "# dialect: cpfg" is no directive
        std::fill(text.begin() + header->begin, text.begin() + header->end, ' ');
    const PreprocessedText preprocessed = runCPreprocessor(text, options.file, preprocess);
    ParseResult result;
    if (!preprocessed.diagnostics.empty()) {
        result.diagnostics = preprocessed.diagnostics;
        return result;
    }
    ParseOptions native = options;
    native.defines.clear(); // already expanded
    result = parseTranslated(Dialect::Cpfg, preprocessed.text, native);
    mapToFiles(preprocessed, result.diagnostics);
    mapToFiles(preprocessed, result.warnings);
    std::vector<Diagnostic> comments = cpfgCommentWarnings(source, options.file);
    result.warnings.insert(result.warnings.begin(), comments.begin(), comments.end());
    result.warnings.insert(result.warnings.end(), preprocessed.warnings.begin(), preprocessed.warnings.end());
    std::stable_sort(result.warnings.begin(), result.warnings.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return std::tie(a.file, a.line, a.column) < std::tie(b.file, b.line, b.column);
    });
    return result;
}

} // namespace

ParseResult parseDialect(std::optional<Dialect> dialect, std::string_view source, const ParseOptions& options) {
    const Dialect chosen = dialect.value_or(detectDialect(source));
    return chosen == Dialect::Cpfg ? parseCpfg(source, options) : parseTranslated(chosen, source, options);
}

Dialect dialectOfFile(std::optional<Dialect> given, std::string_view source, std::string_view path) {
    if (given) return *given;
    if (std::optional<HeaderLine> header = findHeaderLine(source)) return header->dialect;
    return path.ends_with(".l") ? Dialect::Cpfg : Dialect::Native;
}

ParseResult loadDialectFile(const std::string& path, std::optional<Dialect> dialect, ParseOptions options) {
    std::string problem;
    std::string source = readTextFile(path, problem);
    if (options.file == "<input>") options.file = path;
    if (!problem.empty()) {
        ParseResult result;
        result.diagnostics.push_back({path, 0, 0, "cannot read file: it " + problem});
        return result;
    }
    return parseDialect(dialectOfFile(dialect, source, path), source, options);
}

} // namespace lsys
