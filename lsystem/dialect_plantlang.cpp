#include <cctype>
#include <string>

#include "lsystem/dialect.h"
#include "lsystem/lexer.h"

namespace lsys {

namespace {

// One command of the plantlang turtle language and the native module each
// form becomes: plain, with the '<' (reverse) suffix, and with a value.
// Its rotations are clockwise about Forward, Up and Right; a turn clockwise
// about Up is a right turn, ABOP's '-'.
struct Command {
    char letter;
    const char* plain;     // "c" alone
    const char* reversed;  // "c<"
    const char* valued;    // "c(x)" or "cx": the value becomes the module's parameter
};
constexpr Command kCommands[] = {
    {'d', "F", "F(-1)", "F"},              // draw (backwards: one step back)
    {'D', "F", "F(-1)", "@Dp"},            // draw a percentage of the default distance
    {'m', "f", "f(-1)", "f"},              // move
    {'M', "f", "f(-1)", "@Mp"},
    {'f', "/", "\\", "/"},                 // roll about Forward
    {'u', "-", "+", "-"},                  // turn about Up
    {'r', "&", "^", "&"},                  // pitch about Right
    {'t', "@Wa", "@Ws", "!"},              // thickness: add / subtract the default, set
    {'T', "@Wm(1.4)", "@Wm(0.7)", "@Wm"},  // thickness: multiply
    {'o', "@O", "@Ou", "@O"},              // circle (sphere)
    {'O', "@O", "@Ou", "@O"},
    {'c', ";", "@Cs", ";"},                // colour index
    {'a', "@Aa", "@As", "@A"},             // angle: add / subtract the default, set
    {'A', "@Am(1.1)", "@Am(0.9)", "@Am"},  // angle: multiply
    {'l', "@La", "@Ls", "@L"},             // length: add / subtract the default, set
    {'L', "@Lm(1.1)", "@Lm(0.9)", "@Lm"},  // length: multiply
    {'+', "-", "-", "-"},                  // plantlang's + turns right, ABOP's -
    {'-', "+", "+", "+"},
};
constexpr std::string_view kStructure = "[]{}.";

struct Translator {
    std::string_view text;
    const std::string& file;
    Translation out;

    void error(Translation::Origin at, std::string message, std::string expected = {}) {
        out.diagnostics.push_back({file, at.line, at.column, std::move(message), std::move(expected)});
    }

    // "f20t15dX" -> "/(20) !(15) F X"
    std::optional<std::string> word(std::string_view part, Translation::Origin origin) {
        std::string result;
        for (size_t i = 0; i < part.size();) {
            const char c = part[i];
            const Translation::Origin at{origin.line, origin.column + static_cast<int>(i)};
            if (std::isspace(static_cast<unsigned char>(c))) {
                ++i;
                continue;
            }
            ++i;
            const Command* command = nullptr;
            for (const Command& candidate : kCommands)
                if (candidate.letter == c) command = &candidate;
            if (!command) {
                if (!std::isalpha(static_cast<unsigned char>(c)) && kStructure.find(c) == std::string_view::npos) {
                    error(at, std::string("unexpected '") + c + "'", "a turtle command, a variable or a bracket");
                    return std::nullopt;
                }
                result += std::string(1, c) + ' ';  // X, Y, Z and other variables; brackets and polygons
                continue;
            }
            const bool reversed = i < part.size() && part[i] == '<';
            if (reversed) ++i;
            std::string value;
            if (i < part.size() && part[i] == '(') {
                size_t close = part.find(')', i);
                if (close == std::string_view::npos) {
                    error(at, "unclosed value", "')'");
                    return std::nullopt;
                }
                value = part.substr(i + 1, close - i - 1);
                i = close + 1;
            } else {
                while (i < part.size() && (std::isdigit(static_cast<unsigned char>(part[i])) || part[i] == '.')) value += part[i++];
            }
            if (value.empty())
                result += std::string(reversed ? command->reversed : command->plain) + ' ';
            else if (reversed)  // a reversed value: the opposite turn or direction
                result += std::string(command->valued) + "(-(" + value + ")) ";
            else
                result += std::string(command->valued) + "(" + value + ") ";
        }
        return result;
    }

    // "Default angle = 30" and friends.
    bool setting(std::string_view line, Translation::Origin origin) {
        static constexpr std::pair<std::string_view, const char*> kSettings[] = {
            {"default angle", "angle: "}, {"default length", "step: "}, {"default thickness", "width: "},
            {"number of iterations", "derivation length: "}, {"iterations", "derivation length: "}};
        std::string lower;
        for (char c : line) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        for (auto [key, native] : kSettings) {
            if (!lower.starts_with(key)) continue;
            size_t equals = line.find('=');
            if (equals == std::string_view::npos) {
                std::string expected(key);
                error(origin, "missing '='", expected.append(" = value"));
                return true;
            }
            std::string value;
            for (char c : line.substr(equals + 1))  // drops a trailing degree sign or unit
                if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-') value += c;
            out.native += native + value + '\n';
            out.origins.push_back(origin);
            return true;
        }
        return false;
    }

    void line(std::string_view text, int number) {
        size_t start = text.find_first_not_of(" \t");
        if (start == std::string_view::npos) return;
        const Translation::Origin origin{number, static_cast<int>(start) + 1};
        std::string_view content = text.substr(start);
        if (content.starts_with("Rewrite rules")) return;  // a heading in the thesis' listings
        if (setting(content, origin)) return;
        if (content.starts_with("Axiom")) {
            size_t equals = content.find_first_of("=:");
            if (equals == std::string_view::npos) return error(origin, "missing '=' after Axiom", "'Axiom = commands'");
            const int column = origin.column + static_cast<int>(equals) + 1;
            if (auto axiom = word(content.substr(equals + 1), {number, column})) {
                out.native += "Axiom: " + *axiom + '\n';
                out.origins.push_back(origin);
            }
            return;
        }
        // "(0.2) F -> [-F]F": a stochastic rule puts its probability first.
        std::string probability;
        size_t rule = 0;
        if (content.starts_with("(")) {
            size_t close = content.find(')');
            if (close == std::string_view::npos) return error(origin, "unclosed probability", "'(p) X -> successor'");
            probability = content.substr(1, close - 1);
            rule = close + 1;
        }
        size_t arrow = content.find("=>", rule);
        if (arrow == std::string_view::npos) arrow = content.find("->", rule);  // both arrows are two characters
        if (arrow == std::string_view::npos)
            return error(origin, "unrecognised line", "'Axiom = ...', 'X => ...', '(p) X -> ...' or 'Default angle = ...'");
        std::optional<std::string> predecessor = word(content.substr(rule, arrow - rule), {number, origin.column + static_cast<int>(rule)});
        const int successorColumn = origin.column + static_cast<int>(arrow + 2);
        std::optional<std::string> successor = word(content.substr(arrow + 2), {number, successorColumn});
        if (!predecessor || !successor) return;
        out.native += *predecessor + "--> " + *successor + (probability.empty() ? "" : ": " + probability) + '\n';
        out.origins.push_back(origin);
    }
};

}  // namespace

Translation translatePlantlang(std::string_view source, const std::string& file) {
    std::vector<Diagnostic> commentErrors;
    std::string text = blankComments(source, file, commentErrors);
    Translator translator{text, file};
    translator.out.diagnostics = std::move(commentErrors);
    std::vector<std::string_view> lines = splitLines(text);
    for (size_t i = 0; i < lines.size(); ++i) translator.line(lines[i], static_cast<int>(i) + 1);
    return std::move(translator.out);
}

}  // namespace lsys
