#include "lsystem/language/lexer.h"

namespace lsys {

std::string blankComments(std::string_view source, const std::string& file, std::vector<Diagnostic>& diagnostics) {
    std::string out(source);
    int line = 1;
    size_t lineStart = 0;
    for (size_t i = 0; i < out.size(); ++i) {
        if (out[i] == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (out[i] == '/' && i + 1 < out.size() && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
            --i;
        } else if (out[i] == '/' && i + 1 < out.size() && out[i + 1] == '*') {
            int startLine = line;
            int startColumn = static_cast<int>(i - lineStart) + 1;
            out[i] = out[i + 1] = ' ';
            i += 2;
            while (i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/')) {
                if (out[i] == '\n') {
                    ++line;
                    lineStart = i + 1;
                } else {
                    out[i] = ' ';
                }
                ++i;
            }
            if (i >= out.size()) {
                diagnostics.push_back(
                    {file, startLine, startColumn, "unterminated comment", "'*/' before the end of the file"});
                break;
            }
            out[i] = out[i + 1] = ' ';
            ++i;
        }
    }
    return out;
}

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t begin = 0;
    while (begin <= text.size()) {
        size_t end = text.find('\n', begin);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(begin, end - begin);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        begin = end + 1;
    }
    return lines;
}

void Cursor::skipSpaces() {
    while (!atEnd() &&
           (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\r' || text[pos] == '\f' || text[pos] == '\v'))
        ++pos;
}

bool Cursor::accept(std::string_view literal) {
    if (!startsWith(literal)) return false;
    pos += literal.size();
    return true;
}

bool isIdentifierStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentifierChar(char c) { return isIdentifierStart(c) || (c >= '0' && c <= '9'); }

std::string_view Cursor::identifier() {
    if (!isIdentifierStart(peek())) return {};
    size_t begin = pos;
    while (isIdentifierChar(peek())) ++pos;
    return text.substr(begin, pos - begin);
}

Diagnostic errorAt(const Cursor& cursor, const std::string& file, std::string message, std::string expected) {
    return {file, cursor.line, cursor.column(), std::move(message), std::move(expected)};
}

} // namespace lsys
