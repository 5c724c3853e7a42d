#include <algorithm>
#include <cctype>

#include "lsystem/dialect.h"
#include "lsystem/lexer.h"

namespace lsys {

namespace {

constexpr std::string_view kSymbolModules = "+-/\\^&$[]!|%'\"~.";

struct Translator {
    std::string_view text;  // comments already blanked
    const std::string& file;
    Translation out;
    std::vector<std::string> multiLetterModules;
    size_t pos = 0;
    int line = 1;
    size_t lineStart = 0;

    int column() const { return static_cast<int>(pos - lineStart) + 1; }
    char peek(size_t ahead = 0) const { return pos + ahead < text.size() ? text[pos + ahead] : '\0'; }
    void advance() {
        if (peek() == '\n') {
            ++line;
            lineStart = pos + 1;
        }
        ++pos;
    }
    void skipSpace() {
        while (pos < text.size() && std::isspace(static_cast<unsigned char>(peek()))) advance();
    }
    void error(int atLine, int atColumn, std::string message, std::string expected = {}) {
        out.diagnostics.push_back({file, atLine, atColumn, std::move(message), std::move(expected)});
    }
    void emit(std::string native, Translation::Origin origin) {
        out.native += native + '\n';
        out.origins.push_back(origin);
    }

    // {a, b} becomes a uniform draw in [a, b); the rest of an expression is the same in both notations.
    static std::string translateExpression(std::string_view expression) {
        std::string result;
        for (size_t i = 0; i < expression.size(); ++i) {
            size_t comma = expression.find(',', i);
            size_t close = expression.find('}', i);
            if (expression[i] == '{' && comma != std::string_view::npos && close != std::string_view::npos && comma < close) {
                std::string low(expression.substr(i + 1, comma - i - 1)), high(expression.substr(comma + 1, close - comma - 1));
                result += "((" + low + ")+ran((" + high + ")-(" + low + ")))";
                i = close;
            } else {
                result += expression[i];
            }
        }
        return result;
    }

    // Module sequence: names are identifiers (maximal munch) or turtle symbols,
    // each optionally followed (after spaces) by a parenthesised parameter list.
    std::optional<std::string> modules(std::string_view part, Translation::Origin origin) {
        std::string result;
        for (size_t i = 0; i < part.size();) {
            char c = part[i];
            if (std::isspace(static_cast<unsigned char>(c))) {
                ++i;
                continue;
            }
            std::string name;
            if (isIdentifierStart(c)) {
                size_t begin = i;
                while (i < part.size() && isIdentifierChar(part[i])) ++i;
                name = part.substr(begin, i - begin);
                if (name.size() > 1 && std::find(multiLetterModules.begin(), multiLetterModules.end(), name) == multiLetterModules.end())
                    multiLetterModules.push_back(name);
            } else if (kSymbolModules.find(c) != std::string_view::npos) {
                name = std::string(1, c);
                ++i;
            } else {
                error(origin.line, origin.column, std::string("unexpected '") + c + "' in a module list", "a module name");
                return std::nullopt;
            }
            size_t after = i;
            while (after < part.size() && std::isspace(static_cast<unsigned char>(part[after]))) ++after;
            result += name;
            if (after < part.size() && part[after] == '(') {
                int depth = 0;
                size_t close = after;
                for (; close < part.size(); ++close) {
                    if (part[close] == '(') ++depth;
                    if (part[close] == ')' && --depth == 0) break;
                }
                if (close >= part.size()) {
                    error(origin.line, origin.column, "unclosed parameter list", "')'");
                    return std::nullopt;
                }
                result += '(';
                result += translateExpression(part.substr(after + 1, close - after - 1));
                result += ')';
                i = close + 1;
            }
            result += ' ';
        }
        return result;
    }

    // Splits "a : b : c" at top-level colons.
    static std::vector<std::string_view> fields(std::string_view body) {
        std::vector<std::string_view> parts;
        int depth = 0;
        size_t begin = 0;
        for (size_t i = 0; i < body.size(); ++i) {
            if (body[i] == '(' || body[i] == '{') ++depth;
            if (body[i] == ')' || body[i] == '}') --depth;
            if (body[i] == ':' && depth == 0) {
                parts.push_back(body.substr(begin, i - begin));
                begin = i + 1;
            }
        }
        parts.push_back(body.substr(begin));
        return parts;
    }

    static std::string_view trim(std::string_view s) {
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
        return s;
    }

    void statement(std::string_view keyword, std::string_view body, Translation::Origin origin) {
        std::string_view content = trim(body);
        if (keyword == "n") {
            if (content.empty() || content.front() != '=') return error(origin.line, origin.column, "malformed '#n'", "'#n = number;'");
            return emit("derivation length: " + std::string(trim(content.substr(1))), origin);
        }
        if (keyword == "define") return emit("#define " + translateExpression(content), origin);
        if (keyword == "object") return;  // names the shape drawn for a module: nothing to rewrite
        std::vector<std::string_view> parts = fields(content);
        if (keyword == "w") {
            if (parts.size() != 2 || !trim(parts[0]).empty()) return error(origin.line, origin.column, "malformed axiom", "'#w : modules;'");
            if (auto axiom = modules(parts[1], origin)) emit("Axiom: " + *axiom, origin);
            return;
        }
        if (parts.size() != 4 || !trim(parts[0]).empty())
            return error(origin.line, origin.column, "malformed production", "'#" + std::string(keyword) + " : predecessor : condition : successor;'");
        std::optional<std::string> predecessor = modules(parts[1], origin);
        std::optional<std::string> successor = modules(parts[3], origin);
        if (!predecessor || !successor) return;
        std::string_view condition = trim(parts[2]);
        std::string label = keyword.size() > 1 ? std::string(keyword) + ": " : "";
        if (condition == "*") return emit(label + *predecessor + "--> " + *successor, origin);
        if (!condition.empty() && condition.front() == '~')
            return emit(label + *predecessor + "--> " + *successor + ": " + std::string(trim(condition.substr(1))), origin);
        emit(label + *predecessor + ": " + translateExpression(condition) + " --> " + *successor, origin);
    }

    void run() {
        while (true) {
            skipSpace();
            if (pos >= text.size()) break;
            Translation::Origin origin{line, column()};
            if (peek() != '#') {
                error(origin.line, origin.column, std::string("unexpected '") + peek() + "'", "a statement beginning with '#'");
                while (pos < text.size() && peek() != '#') advance();  // resynchronise at the next statement
                continue;
            }
            advance();
            size_t keywordStart = pos;
            while (isIdentifierChar(peek())) advance();
            std::string_view keyword = text.substr(keywordStart, pos - keywordStart);
            size_t bodyStart = pos;
            while (pos < text.size() && peek() != ';' && peek() != '#') advance();
            if (peek() != ';') {
                error(line, column(), "statement not terminated", "';'");
                continue;
            }
            std::string_view body = text.substr(bodyStart, pos - bodyStart);
            advance();
            if (keyword.empty()) {
                error(origin.line, origin.column, "missing statement keyword", "'#n', '#define', '#object', '#w' or a production label");
                continue;
            }
            statement(keyword, body, origin);
        }
        if (!multiLetterModules.empty()) {
            std::string declaration = "module ";
            for (size_t i = 0; i < multiLetterModules.size(); ++i) {
                if (i > 0) declaration += ", ";
                declaration += multiLetterModules[i];
            }
            out.native = declaration + '\n' + out.native;
            out.origins.insert(out.origins.begin(), Translation::Origin{1, 1});
        }
    }
};

}  // namespace

Translation translateCrankshaw(std::string_view source, const std::string& file) {
    std::vector<Diagnostic> commentErrors;
    std::string text = blankComments(source, file, commentErrors);
    Translator translator{text, file};
    translator.out.diagnostics = std::move(commentErrors);
    translator.run();
    return std::move(translator.out);
}

}  // namespace lsys
