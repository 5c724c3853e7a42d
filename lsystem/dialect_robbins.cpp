#include <algorithm>
#include <cctype>

#include "lsystem/dialect.h"
#include "lsystem/lexer.h"

namespace lsys {

namespace {

// Robbins' commands that mean something else (or nothing) in the native
// notation, and the native module each becomes. Scaling commands become the
// turtle's multiplicative modules @Lm (length), @Am (angle), @Wm (width) with
// Robbins' default factor when none is given.
struct Renamed {
    char robbins;
    const char* native;
    const char* defaultParameter;  // added when the command has none, or null
};
constexpr Renamed kRenamed[] = {
    {'>', "/", nullptr},     // roll right
    {'<', "\\", nullptr},    // roll left
    {'%', "/", "180"},       // roll 180 degrees about the heading
    {'"', "@Lm", "1.1"},     // length scale
    {'\'', "@Lm", "0.9"},
    {';', "@Am", "1.1"},     // angle scale
    {':', "@Am", "0.9"},
    {'?', "@Wm", "1.4"},     // thickness scale
    {'!', "@Wm", "0.7"},
};
constexpr std::string_view kCommands = "+-&^<>|%$[]{}\"';:?!.";

struct Module {
    std::string text;  // native spelling
    Translation::Origin origin;
    bool arrow = false;  // the "-->" between a production's name and its successor
};

struct Translator {
    std::string_view text;
    const std::string& file;
    Translation out;
    std::vector<std::string> multiLetterModules;

    void error(Translation::Origin at, std::string message, std::string expected = {}) {
        out.diagnostics.push_back({file, at.line, at.column, std::move(message), std::move(expected)});
    }

    // Splits the text into modules and arrows, reading header keywords first.
    std::vector<Module> scan() {
        std::vector<Module> modules;
        size_t pos = 0, lineStart = 0;
        int line = 1;
        bool inHeader = true;
        auto origin = [&] { return Translation::Origin{line, static_cast<int>(pos - lineStart) + 1}; };
        auto skipSpace = [&] {
            while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) {
                if (text[pos] == '\n') {
                    ++line;
                    lineStart = pos + 1;
                }
                ++pos;
            }
        };
        auto number = [&]() -> std::string {
            skipSpace();
            size_t begin = pos;
            while (pos < text.size() && (std::isdigit(static_cast<unsigned char>(text[pos])) || text[pos] == '.' || text[pos] == '-')) ++pos;
            return std::string(text.substr(begin, pos - begin));
        };
        while (true) {
            skipSpace();
            if (pos >= text.size()) break;
            Translation::Origin at = origin();
            if (text.substr(pos).starts_with("-->")) {
                pos += 3;
                modules.push_back({"-->", at, true});
                continue;
            }
            std::string name;
            if (isIdentifierStart(text[pos])) {
                size_t begin = pos;
                while (pos < text.size() && isIdentifierChar(text[pos])) ++pos;
                name = text.substr(begin, pos - begin);
                static constexpr std::pair<std::string_view, const char*> kHeaders[] = {
                    {"iterations", "derivation length: "}, {"angle", "angle: "}, {"length", "step: "}, {"thickness", "width: "}};
                bool header = false;
                for (auto [keyword, native] : kHeaders)
                    if (inHeader && name == keyword) {
                        std::string value = number();
                        if (value.empty()) {
                            error(origin(), "missing number after '" + name + "'", "a number");
                        } else {
                            out.native += native + value + '\n';
                            out.origins.push_back(at);
                        }
                        header = true;
                    }
                if (inHeader && (name == "startpoint" || name == "forward" || name == "left" || name == "up")) {
                    for (int i = 0; i < 3; ++i)  // the turtle's start frame: plantfield's turtle starts upright
                        if (number().empty()) error(origin(), "'" + name + "' needs three numbers", "a number");
                    header = true;
                }
                if (header) continue;
                if (name.size() > 1 && std::find(multiLetterModules.begin(), multiLetterModules.end(), name) == multiLetterModules.end())
                    multiLetterModules.push_back(name);
            } else if (kCommands.find(text[pos]) != std::string_view::npos) {
                name = std::string(1, text[pos++]);
            } else {
                error(at, std::string("unexpected '") + text[pos] + "'", "a symbol, a production name or '-->'");
                ++pos;
                continue;
            }
            inHeader = false;
            std::string parameter;
            if (pos < text.size() && text[pos] == '(') {
                size_t close = text.find(')', pos);
                if (close == std::string_view::npos || text.substr(pos, close - pos).find('\n') != std::string_view::npos) {
                    error(origin(), "unclosed parameter", "')'");
                    ++pos;
                    continue;
                }
                parameter = text.substr(pos + 1, close - pos - 1);
                pos = close + 1;
            }
            modules.push_back({nativeModule(name, parameter), at});
        }
        return modules;
    }

    static std::string nativeModule(const std::string& name, const std::string& parameter) {
        std::string native = name;
        std::string argument = parameter;
        if (name.size() == 1)
            for (const Renamed& renamed : kRenamed)
                if (renamed.robbins == name[0]) {
                    native = renamed.native;
                    if (argument.empty() && renamed.defaultParameter) argument = renamed.defaultParameter;
                }
        if (!argument.empty()) {
            native += '(';
            native += argument;
            native += ')';
        }
        native += ' ';
        return native;
    }

    void run() {
        std::vector<Module> modules;
        for (Module& module : scan()) {
            if (module.arrow && (modules.empty() || modules.back().arrow)) {
                error(module.origin, "'-->' without a production name", "a name before '-->'");
                continue;  // dropped, so the rest can still be checked
            }
            modules.push_back(std::move(module));
        }
        // A production is "NAME --> successor"; the successor ends where the next name-and-arrow begins.
        std::vector<size_t> arrows;
        for (size_t i = 0; i < modules.size(); ++i)
            if (modules[i].arrow) arrows.push_back(i);
        auto join = [&](size_t begin, size_t end) {
            std::string joined;
            for (size_t i = begin; i < end; ++i) joined += modules[i].text;
            return joined;
        };
        size_t axiomEnd = arrows.empty() ? modules.size() : arrows[0] - 1;
        if (axiomEnd == 0) return error({1, 1}, "no axiom", "the initial symbols before the first production");
        out.native += "Axiom: " + join(0, axiomEnd) + '\n';
        out.origins.push_back(modules[0].origin);
        for (size_t k = 0; k < arrows.size(); ++k) {
            size_t nameIndex = arrows[k] - 1;
            size_t end = k + 1 < arrows.size() ? arrows[k + 1] - 1 : modules.size();
            out.native += modules[nameIndex].text + "--> " + join(arrows[k] + 1, end) + '\n';
            out.origins.push_back(modules[nameIndex].origin);
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

Translation translateRobbins(std::string_view source, const std::string& file) {
    std::vector<Diagnostic> commentErrors;
    std::string text = blankComments(source, file, commentErrors);
    Translator translator{text, file};
    translator.out.diagnostics = std::move(commentErrors);
    translator.run();
    return std::move(translator.out);
}

}  // namespace lsys
