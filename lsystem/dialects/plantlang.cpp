// The turtle command language ("plantlang") of the clouds-and-mountains chapter
// (docs/REFERENCES.md), one statement a line:
//   Axiom = f20t15dt14dt13dX
//   X => t<dt<Yf70Yf132L0.9Y          productions: '=>' or '->'
//   (0.2) F -> [-F]F                   stochastic: the probability first
//   Default angle = 30                 settings: 'name = value' (or 'name: value')
//   Number of iterations = 12
// A command is a letter, optionally followed by '<' (reverse) or a value,
// written (20) or 20. Every command becomes one native module (nativeCommand);
// the default increments and factors, and the default length that D, M and
// the backward moves use, are settings read before translating.

#include <cctype>
#include <charconv>
#include <cstring>
#include <functional>
#include <optional>

#include "lsystem/dialects/native_text.h"

namespace lsys {

namespace {

struct Defaults {
    double length = 1;
    double lengthIncrement = 1, angleIncrement = 1, thicknessIncrement = 1;
    double lengthFactor = 0.9, angleFactor = 0.9, thicknessFactor = 0.9;
};

struct Setting {
    std::string_view name;   // lower case, single spaces
    std::string_view native; // native header written with the value; empty: none
    double Defaults::*value; // default used by the translation; nullptr: none
};

constexpr Setting kSettings[] = {
    {"default angle", "angle: ", nullptr},
    {"default length", "step: ", &Defaults::length},
    {"default distance", "step: ", &Defaults::length},
    {"default thickness", "width: ", nullptr},
    {"number of iterations", "derivation length: ", nullptr},
    {"iterations", "derivation length: ", nullptr},
    {"seed", "seed: ", nullptr},
    {"length increment", "", &Defaults::lengthIncrement},
    {"angle increment", "", &Defaults::angleIncrement},
    {"thickness increment", "", &Defaults::thicknessIncrement},
    {"length factor", "", &Defaults::lengthFactor},
    {"angle factor", "", &Defaults::angleFactor},
    {"thickness factor", "", &Defaults::thicknessFactor},
};

std::string call(std::string_view name, double value) { return std::string(name) + "(" + formatNumber(value) + ")"; }

// The native module for one command; nullopt when the command does not take
// the '<' or the value it was given.
std::optional<std::string> nativeCommand(char c, bool reversed, std::optional<double> value, const Defaults& d) {
    // bare, reversed ('<') and with a value
    auto pick = [&](std::string bare, std::string back,
                    const std::function<std::string(double)>& withValue) -> std::optional<std::string> {
        if (value) return withValue(*value);
        return reversed ? back : bare;
    };
    auto plain = [&](std::string bare) -> std::optional<std::string> {
        if (value || reversed) return std::nullopt;
        return bare;
    };
    auto times = [](std::string_view name) { return [name](double x) { return call(name, x); }; };
    switch (c) {
    case 'd':
    case 'F': return pick("F", call("F", -d.length), times("F")); // F is the chapter's older name for d
    case 'D': return pick("F", call("F", -d.length), [&](double x) { return call("F", x * d.length / 100); });
    case 'm': return pick("f", call("f", -d.length), times("f"));
    case 'M': return pick("f", call("f", -d.length), [&](double x) { return call("f", x * d.length / 100); });
    // Clockwise as seen from the tip of the axis: about Forward is roll right,
    // about Up turn right, about Right pitch down (ABOP / \, - +, & ^).
    case 'f': return pick("/", "\\", times("/"));
    case 'u': return pick("-", "+", times("-"));
    case 'r': return pick("&", "^", times("&"));
    case '+': return plain("-"); // plantlang turns right on '+', ABOP left
    case '-': return plain("+");
    case 't': return pick(call("@Wa", d.thicknessIncrement), call("@Wa", -d.thicknessIncrement), times("!"));
    case 'T': return pick(call("@Wm", d.thicknessFactor), call("@Wm", 1 / d.thicknessFactor), times("@Wm"));
    case 'o':
    case 'O': return pick("@O", "@Oc", times("@O")); // sphere; '<' an unfilled circle
    case 'c': return pick(";", call("@Ca", -1), times(";"));
    case 'a': return pick(call("@Aa", d.angleIncrement), call("@Aa", -d.angleIncrement), times("@As"));
    case 'A': return pick(call("@Am", d.angleFactor), call("@Am", 1 / d.angleFactor), times("@Am"));
    case 'l': return pick(call("@La", d.lengthIncrement), call("@La", -d.lengthIncrement), times("@Ls"));
    case 'L': return pick(call("@Lm", d.lengthFactor), call("@Lm", 1 / d.lengthFactor), times("@Lm"));
    case '[':
    case ']':
    case '{':
    case '}':
    case '.': return plain(std::string(1, c));
    default: return plain(std::string(1, c)); // a variable such as X, Y, Z
    }
}

bool isCommand(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || (c != '\0' && std::strchr("+-[]{}.", c));
}

std::string lowerWords(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (std::isspace(static_cast<unsigned char>(c))) {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
    }
    if (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

std::optional<double> parseNumber(std::string_view text) {
    double value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

struct Plantlang {
    const Source& source;
    NativeText out{source};
    Defaults defaults;
    std::vector<Diagnostic> diagnostics;

    void fail(size_t offset, std::string message, std::string expected = {}) {
        diagnostics.push_back(source.diagnostic(offset, std::move(message), std::move(expected)));
    }

    std::string_view lineAt(size_t begin) const {
        std::string_view text = source.text;
        size_t end = text.find('\n', begin);
        std::string_view line =
            text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
        if (line.ends_with('\r')) line.remove_suffix(1);
        return line;
    }

    // "name = value": the setting and the value's offset; nullopt (and a
    // diagnostic when report) if the line is not a valid setting.
    std::optional<std::pair<const Setting*, double>> setting(size_t begin, bool report) {
        std::string_view line = lineAt(begin);
        size_t separator = line.find_first_of("=:");
        if (separator == std::string_view::npos) return std::nullopt;
        std::string name = lowerWords(line.substr(0, separator));
        const Setting* found = nullptr;
        for (const Setting& candidate : kSettings)
            if (candidate.name == name) found = &candidate;
        if (!found) {
            if (report)
                fail(begin + line.find_first_not_of(" \t"), "unknown setting '" + name + "'",
                     "'Default angle', 'Default length', 'Default thickness', 'Number of iterations', 'Seed', or an "
                     "increment or factor");
            return std::nullopt;
        }
        std::string_view value = line.substr(separator + 1);
        size_t first = value.find_first_not_of(" \t");
        size_t last = value.find_last_not_of(" \t");
        std::optional<double> number =
            first == std::string_view::npos ? std::nullopt : parseNumber(value.substr(first, last - first + 1));
        if (!number) {
            if (report)
                fail(begin + separator + 1 + (first == std::string_view::npos ? 0 : first),
                     "the value of '" + name + "' is not a number", "a number");
            return std::nullopt;
        }
        return std::make_pair(found, *number);
    }

    // A value after a command: (number) or a bare unsigned number.
    std::optional<double> commandValue(Scanner& s, bool& ok) {
        size_t begin = s.pos;
        if (s.accept("(")) {
            s.skipSpaces();
            size_t numberAt = s.pos;
            bool negative = s.accept("-");
            std::string_view digits = s.number();
            s.skipSpaces();
            if (digits.empty() || !s.accept(")")) {
                ok = false;
                fail(digits.empty() ? numberAt : s.pos, "malformed value", "a number in parentheses such as (20)");
                return std::nullopt;
            }
            return (negative ? -1 : 1) * *parseNumber(digits);
        }
        std::string_view digits = s.number();
        if (digits.empty()) {
            s.pos = begin;
            return std::nullopt;
        }
        return *parseNumber(digits);
    }

    // One command, translated and appended; false on error.
    bool command(Scanner& s, Statement& into) {
        size_t at = s.pos;
        char c = s.peek();
        if (!isCommand(c)) {
            fail(at, std::string("unknown command '") + c + "'", "a command letter, + - [ ] { } or .");
            return false;
        }
        ++s.pos;
        bool reversed = s.accept("<");
        bool ok = true;
        std::optional<double> value = reversed ? std::nullopt : commandValue(s, ok);
        if (!ok) return false;
        std::optional<std::string> native = nativeCommand(c, reversed, value, defaults);
        if (!native) {
            fail(at + 1, std::string("'") + c + "' takes no " + (reversed ? "'<'" : "value"));
            return false;
        }
        if (!into.text.empty()) into.emit(" ", at);
        into.emit(*native, at);
        return true;
    }

    bool commands(Scanner& s, Statement& into) {
        while (true) {
            s.skipSpaces();
            if (s.atLineEnd()) return true;
            if (!command(s, into)) return false;
        }
    }

    void axiom(Scanner& s) {
        s.identifier(); // "Axiom"
        s.skipSpaces();
        s.accept("=") || s.accept(":");
        Statement st = out.start(s.pos);
        st.emit("Axiom:", s.pos);
        if (commands(s, st)) out.add(std::move(st));
    }

    // [(probability)] predecessor => successor
    void production(Scanner& s) {
        Statement st = out.start(s.pos), predecessor, probability;
        if (s.accept("(")) {
            s.skipSpaces();
            size_t numberAt = s.pos;
            std::string_view digits = s.number();
            s.skipSpaces();
            if (digits.empty() || !s.accept(")"))
                return fail(digits.empty() ? numberAt : s.pos, "malformed probability",
                            "a number in parentheses such as (0.2)");
            probability.copy(digits, numberAt);
            s.skipSpaces();
        }
        size_t predecessorAt = s.pos;
        if (!command(s, predecessor)) return;
        if (predecessor.text.find_first_of("( ") != std::string::npos)
            return fail(predecessorAt, "a production must rewrite a letter or symbol without a value",
                        "a variable such as X");
        s.skipSpaces();
        if (!s.accept("=>") && !s.accept("-->") && !s.accept("->"))
            return fail(s.pos, "missing arrow after the predecessor", "'=>'");
        Statement successor;
        if (!commands(s, successor)) return;
        st.append(predecessor);
        st.emit(" --> ", predecessorAt);
        st.append(successor);
        if (!probability.text.empty()) st.emit(" : ", predecessorAt), st.append(probability);
        out.add(std::move(st));
    }

    void settingLine(size_t begin) {
        std::optional<std::pair<const Setting*, double>> found = setting(begin, true);
        if (!found || found->first->native.empty()) return;
        Statement st = out.start(begin);
        st.emit(std::string(found->first->native) + formatNumber(found->second), begin);
        out.add(std::move(st));
    }

    Translation run() {
        std::vector<size_t> lines;
        for (size_t begin : source.lineStarts)
            if (lineAt(begin).find_first_not_of(" \t") != std::string_view::npos) lines.push_back(begin);
        // Settings first: commands anywhere in the file use the defaults.
        for (size_t begin : lines)
            if (auto found = setting(begin, false); found && found->first->value)
                defaults.*(found->first->value) = found->second;
        for (size_t begin : lines) {
            std::string_view line = lineAt(begin);
            Scanner s{source, begin};
            s.skipSpaces();
            size_t separator = line.find_first_of("=:");
            if (separator != std::string_view::npos && lowerWords(line.substr(0, separator)) == "axiom")
                axiom(s);
            else if (line.find("=>") != std::string_view::npos || line.find("->") != std::string_view::npos)
                production(s);
            else if (separator != std::string_view::npos)
                settingLine(begin);
            else
                fail(s.pos, "unrecognised line",
                     "'Axiom = ...', a production 'X => ...' or a setting 'Default angle = 30'");
        }
        return out.finish(std::move(diagnostics));
    }
};

} // namespace

Translation translatePlantlang(const Source& source) { return Plantlang{source}.run(); }

} // namespace lsys
