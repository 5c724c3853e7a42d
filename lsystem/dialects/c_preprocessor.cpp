#include "lsystem/dialects/c_preprocessor.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "lsystem/common/subprocess.h"
#include "lsystem/language/lexer.h"
#include "lsystem/language/parser.h"

namespace lsys {

namespace {

// The name cpp gives the text it reads from its standard input.
constexpr std::string_view kStandardInput = "<stdin>";

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// `source` with each object-like "#define NAME ..." of an overridden NAME
// giving the override's value instead (on the same line, so lines keep their
// numbers); the overrides the source never defines are returned in `unused`.
std::string applyOverrides(std::string_view source, const PreprocessOptions& options,
                           std::vector<std::pair<std::string, std::string>>& unused) {
    std::string out;
    std::vector<bool> used(options.macros.size(), false);
    const std::vector<std::string_view> lines = splitLines(source);
    for (size_t index = 0; index < lines.size(); ++index) {
        const std::string_view line = lines[index];
        if (index > 0) out += '\n';
        size_t at = 0;
        auto skip = [&] {
            while (at < line.size() && isSpace(line[at])) ++at;
        };
        skip();
        bool replaced = false;
        if (at < line.size() && line[at] == '#') {
            ++at;
            skip();
            if (line.substr(at).starts_with("define") && at + 6 < line.size() && isSpace(line[at + 6])) {
                at += 6;
                skip();
                size_t nameEnd = at;
                while (nameEnd < line.size() &&
                       (std::isalnum(static_cast<unsigned char>(line[nameEnd])) || line[nameEnd] == '_'))
                    ++nameEnd;
                const std::string_view name = line.substr(at, nameEnd - at);
                const bool functionLike = nameEnd < line.size() && line[nameEnd] == '(';
                for (size_t i = 0; i < options.macros.size() && !functionLike; ++i)
                    if (options.macros[i].first == name) {
                        out += line.substr(0, nameEnd);
                        out += ' ' + options.macros[i].second;
                        used[i] = replaced = true;
                        break;
                    }
            }
        }
        if (!replaced) out += line;
    }
    for (size_t i = 0; i < options.macros.size(); ++i)
        if (!used[i]) unused.push_back(options.macros[i]);
    return out;
}

std::vector<std::string> commandLine(const std::string& file, const PreprocessOptions& options,
                                     const std::vector<std::pair<std::string, std::string>>& macros) {
    // GNU C89 is cccp's language: // comments, no digraphs (so "%:" is two
    // modules, not "#") and no trigraphs. As assembler source, a line that
    // starts with '#' but no directive (a tab-continued "#(0.1) F", a
    // production "#(w) --> ...") is passed on as text, as vlabcpp passes it
    // on after its complaint (Reader::nonDirective). No
    // predefined macros ("unix", "linux" are not modules' parameters), no
    // system headers, and "$" — a turtle module — ends a name so that a
    // macro before it still expands.
    std::vector<std::string> argv{options.program,
                                  "-x",
                                  "assembler-with-cpp",
                                  "-std=gnu89",
                                  "-undef",
                                  "-nostdinc",
                                  "-w",
                                  "-fno-dollars-in-identifiers",
                                  "-fdiagnostics-column-unit=byte",
                                  "-fdiagnostics-plain-output"};
    std::vector<std::string> directories = options.includeDirectories;
    if (const size_t slash = file.rfind('/'); slash != std::string::npos)
        directories.insert(directories.begin(), file.substr(0, std::max<size_t>(slash, 1)));
    for (const std::string& directory : directories) argv.push_back("-I" + directory);
    for (const auto& [name, value] : macros) argv.push_back("-D" + name + "=" + value);
    argv.push_back("-");
    return argv;
}

int parseInt(std::string_view text) {
    int value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
}

// The files' lines, found once per file: the preprocessor's output is
// matched to its source line by line, and a rescan per line would make
// reading a long file quadratic.
class SourceLines {
public:
    explicit SourceLines(const std::vector<std::string>& texts) : texts_(texts) {}

    // Line `line` (1-based) of file `file`, empty past its end.
    std::string_view line(uint32_t file, int line) {
        if (starts_.size() <= file) starts_.resize(file + 1);
        std::vector<size_t>& starts = starts_[file];
        const std::string_view text = texts_[file];
        if (starts.empty()) {
            starts.push_back(0);
            for (size_t i = 0; i < text.size(); ++i)
                if (text[i] == '\n') starts.push_back(i + 1);
        }
        if (line < 1 || static_cast<size_t>(line) > starts.size()) return {};
        const size_t begin = starts[static_cast<size_t>(line) - 1];
        return text.substr(begin, std::min(text.find('\n', begin), text.size()) - begin);
    }

private:
    const std::vector<std::string>& texts_;
    std::vector<std::vector<size_t>> starts_; // per file, where each line begins
};

struct Reader {
    PreprocessedText& out;
    SourceLines lines{out.fileTexts};

    uint32_t fileIndex(const std::string& name) {
        const std::string shown = name == kStandardInput ? out.files[0] : name;
        for (uint32_t i = 0; i < out.files.size(); ++i)
            if (out.files[i] == shown) return i;
        std::string problem;
        out.files.push_back(shown);
        out.fileTexts.push_back(readTextFile(shown, problem));
        return static_cast<uint32_t>(out.files.size() - 1);
    }

    std::string_view sourceLine(PreprocessedText::Origin origin) { return lines.line(origin.file, origin.line); }

    // '# 12 "name" 1 2': the next line is line 12 of "name". (A line "# 12"
    // without a name is the user's, passed on as text.)
    bool marker(std::string_view line, PreprocessedText::Origin& next) {
        if (line.size() < 3 || line[0] != '#' || line[1] != ' ' || !std::isdigit(static_cast<unsigned char>(line[2])))
            return false;
        const size_t quote = line.find('"');
        if (quote == std::string_view::npos) return false;
        std::string name;
        for (size_t i = quote + 1; i < line.size() && line[i] != '"'; ++i)
            name += line[i] == '\\' && i + 1 < line.size() ? line[++i] : line[i];
        next = {fileIndex(name), parseInt(line.substr(2))};
        return true;
    }

    // A line of the user's that begins with '#' but is no directive (a
    // production of the width module, "#(w) --> #(w + 1)") comes out as it
    // went in: cpp reads assembler here, and cpfg's vlabcpp reports the line
    // as an invalid preprocessing directive but passes it on too, so that
    // cpfg reads it as a production. A warning says so.
    void nonDirective(std::string_view text, PreprocessedText::Origin origin) {
        auto firstIsHash = [](std::string_view line) {
            const size_t first = line.find_first_not_of(" \t");
            return first != std::string_view::npos && line[first] == '#';
        };
        const std::string_view source = sourceLine(origin);
        if (!firstIsHash(text) || !firstIsHash(source)) return;
        out.warnings.push_back({out.files[origin.file],
                                origin.line,
                                static_cast<int>(source.find('#')) + 1,
                                "'#' begins a line but no directive: cpfg's preprocessor reports an invalid "
                                "preprocessing directive here and passes the line on as text, as it is read here",
                                {},
                                origin.file != 0 ? std::string(source) : std::string(),
                                Severity::Warning});
    }

    void read(std::string_view output) {
        PreprocessedText::Origin next{0, 1};
        for (std::string_view line : splitLines(output)) {
            if (marker(line, next)) continue;
            std::string text(line);
            // cpp keeps a token's column with spaces; a tab at the start of the
            // original line is what makes it a continuation for cpfg.
            if (sourceLine(next).starts_with('\t') && text.starts_with(' ')) {
                const size_t indent = text.find_first_not_of(' ');
                text = '\t' + (indent == std::string::npos ? std::string() : text.substr(indent));
            }
            nonDirective(text, next);
            if (!out.lines.empty()) out.text += '\n';
            out.text += text;
            out.lines.push_back(next);
            ++next.line;
        }
    }

    // "<stdin>:3:8: error: message" (fatal errors too); notes, "In file
    // included from" lines and the rest of cpp's chatter are left out.
    void readErrors(std::string_view errors) {
        for (std::string_view line : splitLines(errors)) {
            for (std::string_view kind : {": fatal error: ", ": error: "}) {
                const size_t at = line.find(kind);
                if (at == std::string_view::npos) continue;
                std::string_view where = line.substr(0, at);
                Diagnostic diagnostic{out.files[0], 0, 0, std::string(line.substr(at + kind.size())), {}};
                // "name:line:column" or, for some errors, "name:line".
                auto number = [&](std::string_view& text) {
                    const size_t colon = text.rfind(':');
                    if (colon == std::string_view::npos || colon + 1 == text.size() ||
                        text.substr(colon + 1).find_first_not_of("0123456789") != std::string_view::npos)
                        return 0;
                    const int value = parseInt(text.substr(colon + 1));
                    text = text.substr(0, colon);
                    return value;
                };
                const int last = number(where), previous = number(where);
                if (last > 0) {
                    const uint32_t file = fileIndex(std::string(where));
                    diagnostic.file = out.files[file];
                    diagnostic.line = previous > 0 ? previous : last;
                    diagnostic.column = previous > 0 ? last : 1;
                    if (file != 0) diagnostic.sourceLine = sourceLine({file, diagnostic.line});
                }
                out.diagnostics.push_back(std::move(diagnostic));
                break;
            }
        }
    }
};

// The byte of `source` that byte `at` of `output` (the same line after
// preprocessing) came from: the two are aligned by their longest common
// subsequence, white space matching white space, so removed comments,
// collapsed spaces and expanded macros (which point at the macro's name)
// are accounted for.
size_t alignedOffset(std::string_view output, std::string_view source, size_t at) {
    if (output == source) return at;
    constexpr size_t kLongest = 1024; // longer lines keep their columns: a quadratic table would be too big
    if (output.size() > kLongest || source.size() > kLongest) return std::min(at, source.size());
    const size_t n = output.size(), m = source.size();
    auto same = [&](size_t i, size_t j) {
        return output[i] == source[j] || (isSpace(output[i]) && isSpace(source[j]));
    };
    // common[i][j]: the longest common subsequence of output[i..] and source[j..].
    std::vector<uint16_t> common((n + 1) * (m + 1), 0);
    auto cell = [&](size_t i, size_t j) -> uint16_t& { return common[i * (m + 1) + j]; };
    for (size_t i = n; i-- > 0;)
        for (size_t j = m; j-- > 0;)
            cell(i, j) = same(i, j) ? uint16_t(cell(i + 1, j + 1) + 1) : std::max(cell(i + 1, j), cell(i, j + 1));
    size_t i = 0, j = 0, afterMatch = 0; // afterMatch: the source byte after the last one matched
    while (i < n && j < m) {
        if (same(i, j) && cell(i, j) == cell(i + 1, j + 1) + 1) {
            if (i == at) return j;
            afterMatch = j + 1;
            ++i, ++j;
        } else if (cell(i + 1, j) >= cell(i, j + 1)) {
            if (i == at) break; // generated text: it stands for what follows the last match
            ++i;
        } else {
            ++j;
        }
    }
    while (afterMatch < m && isSpace(source[afterMatch])) ++afterMatch;
    return afterMatch;
}

} // namespace

PreprocessedText runCPreprocessor(std::string_view source, const std::string& file, const PreprocessOptions& options) {
    PreprocessedText out;
    out.files.push_back(file);
    out.fileTexts.emplace_back(source);
    std::vector<std::pair<std::string, std::string>> added;
    const std::string input = applyOverrides(source, options, added);
    const ProcessResult run = runProcess(commandLine(file, options, added), input);
    Reader reader{out};
    if (!run.started || !run.failure.empty()) {
        out.diagnostics.push_back(
            {file,
             0,
             0,
             "cpfg files are read through the C preprocessor, as cpfg reads them, but " + run.failure +
                 (run.started ? std::string() : " (Debian's package cpp provides it; tools/deps.sh installs it)"),
             {}});
        return out;
    }
    reader.readErrors(run.err);
    if (run.exitCode != 0 && out.diagnostics.empty())
        out.diagnostics.push_back({file,
                                   0,
                                   0,
                                   "the C preprocessor failed (it may use " +
                                       std::to_string(ProcessLimits{}.maxMemoryBytes >> 20) + " MiB): " + run.err,
                                   {}});
    reader.read(run.out);
    return out;
}

void mapToFiles(const PreprocessedText& preprocessed, std::vector<Diagnostic>& diagnostics) {
    const std::vector<std::string_view> outputLines = splitLines(preprocessed.text);
    SourceLines lines(preprocessed.fileTexts);
    for (Diagnostic& diagnostic : diagnostics) {
        if (diagnostic.line < 1 || static_cast<size_t>(diagnostic.line) > preprocessed.lines.size()) continue;
        const PreprocessedText::Origin origin = preprocessed.lines[static_cast<size_t>(diagnostic.line) - 1];
        const std::string_view sourceLine = lines.line(origin.file, origin.line);
        const size_t at = static_cast<size_t>(std::max(diagnostic.column, 1)) - 1;
        diagnostic.column =
            static_cast<int>(alignedOffset(outputLines[static_cast<size_t>(diagnostic.line) - 1], sourceLine, at)) + 1;
        diagnostic.file = preprocessed.files[origin.file];
        diagnostic.line = origin.line;
        if (origin.file != 0) diagnostic.sourceLine = sourceLine;
    }
}

} // namespace lsys
