#include "lsystem/dialects/native_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "lsystem/language/lexer.h"

namespace lsys {

Source::Source(std::string_view original, std::string file_, std::vector<Diagnostic>& diagnostics)
    : file(std::move(file_)), text(blankComments(original, file, diagnostics)) {
    if (std::optional<HeaderLine> header = findHeaderLine(text))
        std::fill(text.begin() + header->begin, text.begin() + header->end, ' ');
    lineStarts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') lineStarts.push_back(i + 1);
}

int Source::lineOf(size_t offset) const {
    return static_cast<int>(std::upper_bound(lineStarts.begin(), lineStarts.end(), offset) - lineStarts.begin());
}

Diagnostic Source::diagnostic(size_t offset, std::string message, std::string expected) const {
    int line = lineOf(offset);
    return {file, line, static_cast<int>(offset - lineStarts[line - 1]) + 1, std::move(message), std::move(expected)};
}

char Scanner::peek(size_t ahead) const { return pos + ahead < source.text.size() ? source.text[pos + ahead] : '\0'; }

bool Scanner::accept(std::string_view literal) {
    if (std::string_view(source.text).substr(pos).starts_with(literal)) {
        pos += literal.size();
        return true;
    }
    return false;
}

void Scanner::skipSpaces() {
    while (peek() == ' ' || peek() == '\t') ++pos;
}

void Scanner::skipWhitespace() {
    while (!atEnd() && std::isspace(static_cast<unsigned char>(peek()))) ++pos;
}

std::string_view Scanner::identifier() {
    size_t begin = pos;
    if (isIdentifierStart(peek()))
        while (isIdentifierChar(peek())) ++pos;
    return std::string_view(source.text).substr(begin, pos - begin);
}

std::string_view Scanner::number() {
    size_t begin = pos;
    auto digits = [&] {
        size_t start = pos;
        while (std::isdigit(static_cast<unsigned char>(peek()))) ++pos;
        return pos > start;
    };
    bool whole = digits();
    bool fraction = peek() == '.' && std::isdigit(static_cast<unsigned char>(peek(1))) && (++pos, digits());
    if (!whole && !fraction) {
        pos = begin;
        return {};
    }
    size_t beforeExponent = pos;
    if (peek() == 'e' || peek() == 'E') {
        ++pos;
        if (peek() == '+' || peek() == '-') ++pos;
        if (!digits()) pos = beforeExponent;
    }
    return std::string_view(source.text).substr(begin, pos - begin);
}

void Statement::copy(std::string_view piece, size_t sourceOffset) {
    text += piece;
    for (size_t i = 0; i < piece.size(); ++i) origin.push_back(static_cast<uint32_t>(sourceOffset + i));
}

void Statement::emit(std::string_view piece, size_t sourceOffset) {
    text += piece;
    origin.insert(origin.end(), piece.size(), static_cast<uint32_t>(sourceOffset));
}

void Statement::append(const Statement& other) {
    text += other.text;
    origin.insert(origin.end(), other.origin.begin(), other.origin.end());
}

Statement NativeText::start(size_t sourceOffset) const {
    Statement statement;
    statement.preferredLine = source_.lineOf(sourceOffset);
    return statement;
}

Translation NativeText::finish(std::vector<Diagnostic> diagnostics) const {
    Translation out;
    out.diagnostics = std::move(diagnostics);
    int line = 0; // native lines written so far
    auto place = [&](const Statement& statement) {
        int target = std::max(statement.preferredLine, line + 1);
        // Blank lines stand for the dialect lines that hold no statement; they come from the end of the previous line.
        uint32_t blankOrigin = out.origin.empty() ? 0 : out.origin.back();
        for (; line + 1 < target; ++line) {
            out.nativeSource += '\n';
            out.origin.push_back(blankOrigin);
        }
        out.nativeSource += statement.text;
        out.origin.insert(out.origin.end(), statement.origin.begin(), statement.origin.end());
        // The end of the line is just past its last byte, where a problem at the end of a statement is shown.
        out.nativeSource += '\n';
        out.origin.push_back(statement.origin.empty() ? blankOrigin : statement.origin.back() + 1);
        ++line;
    };
    for (const auto* group : {&leading_, &body_, &trailing_})
        for (const Statement& statement : *group) place(statement);
    return out;
}

void ModuleNames::use(std::string_view name, size_t sourceOffset) {
    if (name.size() < 2) return;
    if (multiLetter.empty()) firstUse = sourceOffset;
    multiLetter.emplace(name);
}

void ModuleNames::declare(NativeText& out) const {
    if (multiLetter.empty()) return;
    Statement statement;
    statement.emit("module ", firstUse);
    for (const std::string& name : multiLetter) {
        if (&name != &*multiLetter.begin()) statement.emit(", ", firstUse);
        statement.emit(name, firstUse);
    }
    out.addFirst(std::move(statement));
}

std::string formatNumber(double value) {
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : "0";
}

namespace {

// "dialect: NAME", alone on its line after an optional comment opener.
std::optional<Dialect> headerDialect(std::string_view line) {
    auto skipSpaces = [&] { line.remove_prefix(std::min(line.size(), line.find_first_not_of(" \t\r"))); };
    auto accept = [&](std::string_view word) { // case-insensitive
        if (line.size() < word.size()) return false;
        for (size_t i = 0; i < word.size(); ++i)
            if (std::tolower(static_cast<unsigned char>(line[i])) != word[i]) return false;
        line.remove_prefix(word.size());
        return true;
    };
    skipSpaces();
    accept("//") || accept("/*") || accept("#");
    skipSpaces();
    if (!accept("dialect")) return std::nullopt;
    skipSpaces();
    if (!accept(":")) return std::nullopt;
    skipSpaces();
    size_t nameEnd = 0;
    while (nameEnd < line.size() && std::isalpha(static_cast<unsigned char>(line[nameEnd]))) ++nameEnd;
    std::optional<Dialect> dialect = dialectFromName(line.substr(0, nameEnd));
    line.remove_prefix(nameEnd);
    skipSpaces();
    if (accept("*/")) skipSpaces();
    return line.empty() ? dialect : std::nullopt;
}

} // namespace

std::optional<HeaderLine> findHeaderLine(std::string_view source) {
    for (size_t begin = 0; begin < source.size();) {
        size_t end = std::min(source.find('\n', begin), source.size());
        std::string_view line = source.substr(begin, end - begin);
        if (line.find_first_not_of(" \t\r") != std::string_view::npos) { // the first non-blank line
            std::optional<Dialect> dialect = headerDialect(line);
            if (!dialect) return std::nullopt;
            return HeaderLine{begin, end, *dialect};
        }
        begin = end + 1;
    }
    return std::nullopt;
}

} // namespace lsys
