#include "lsystem/language/module_string.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "lsystem/common/memory_budget.h"

namespace lsys {

void ModuleString::clear() {
    symbols.clear();
    paramStart.clear();
    params.clear();
}

void ModuleString::addOffsets() {
    if (!paramStart.empty()) return;
    paramStart.assign(symbols.size() + 1, static_cast<uint32_t>(params.size()));
}

void ModuleString::push(SymbolId symbol, std::span<const float> parameters) {
    if (!parameters.empty()) addOffsets();
    symbols.push_back(symbol);
    if (!paramStart.empty()) {
        params.insert(params.end(), parameters.begin(), parameters.end());
        paramStart.push_back(static_cast<uint32_t>(params.size()));
    }
}

uint64_t moduleStringBytes(uint64_t modules, uint64_t parameters, bool offsets) {
    const uint64_t perModule = sizeof(SymbolId) + (offsets ? sizeof(uint32_t) : 0);
    return bytesPlus(bytesTimes(modules, perModule), bytesTimes(parameters, sizeof(float)));
}

namespace {

// Appends module i as "F(1,0.5)": parameters with %g (their float value, as
// cpfg and lpfg print them). Returns the characters appended, commas left out.
size_t appendModule(std::string& out, const ModuleString& string, const SymbolTable& symbols, size_t i) {
    const size_t before = out.size();
    out += symbols.name(string.symbols[i]);
    std::span<const float> parameters = string.parameters(i);
    if (parameters.empty()) return out.size() - before;
    char buffer[32];
    out += '(';
    for (size_t p = 0; p < parameters.size(); ++p) {
        if (p > 0) out += ',';
        // printf's %g (general form, 6 significant digits), several times faster than snprintf.
        const std::to_chars_result written = std::to_chars(
            buffer, buffer + sizeof buffer, static_cast<double>(parameters[p]), std::chars_format::general, 6);
        out.append(buffer, written.ptr);
    }
    out += ')';
    return out.size() - before - (parameters.size() - 1);
}

} // namespace

void writeText(const ModuleString& string, const SymbolTable& symbols, TextLayout layout,
               const std::function<void(std::string_view)>& write) {
    constexpr size_t kLineLength = 70; // cpfg's
    constexpr size_t kChunk = size_t(1) << 20;
    std::string out;
    out.reserve(kChunk + 4096);
    size_t onLine = 0;
    for (size_t i = 0; i < string.size(); ++i) {
        if (layout == TextLayout::Cpfg && onLine >= kLineLength) {
            out += '\n';
            onLine = 0;
        }
        onLine += appendModule(out, string, symbols, i);
        if (out.size() >= kChunk) {
            write(out);
            out.clear();
        }
    }
    if (layout == TextLayout::Cpfg) out += '\n';
    write(out);
}

std::string toString(const ModuleString& string, const SymbolTable& symbols) {
    std::string out;
    out.reserve(string.size());
    writeText(string, symbols, TextLayout::OneLine, [&](std::string_view chunk) { out += chunk; });
    return out;
}

std::string toCpfgString(const ModuleString& string, const SymbolTable& symbols) {
    std::string out;
    out.reserve(string.size() + string.size() / 70 + 1);
    writeText(string, symbols, TextLayout::Cpfg, [&](std::string_view chunk) { out += chunk; });
    return out;
}

namespace {

// The text without its line breaks, and where each of its modules begins is
// found as the comparison goes.
struct TextCursor {
    std::string text;
    size_t pos = 0;
    std::string_view from(size_t at, size_t length = 24) const { return std::string_view(text).substr(at, length); }
};

bool closeEnough(double a, double b, double tolerance) {
    return std::fabs(a - b) <= std::max(tolerance * std::max(std::fabs(a), std::fabs(b)), 1e-6);
}

} // namespace

std::optional<std::string> firstDifference(const ModuleString& string, const SymbolTable& symbols,
                                           std::string_view text, double tolerance) {
    TextCursor cursor;
    cursor.text.reserve(text.size());
    for (char c : text)
        if (c != '\n' && c != '\r') cursor.text += c;
    std::string ours;
    for (size_t i = 0; i < string.size(); ++i) {
        ours.clear();
        appendModule(ours, string, symbols, i);
        const size_t start = cursor.pos;
        auto differs = [&](const std::string& why) {
            const std::string_view theirs = cursor.from(start);
            return "module " + std::to_string(i) + ": " + why + ": derived " + ours + ", the text has " +
                   (theirs.empty() ? std::string("nothing") : std::string(theirs) + "...");
        };
        const std::string& name = symbols.name(string.symbols[i]);
        if (!std::string_view(cursor.text).substr(cursor.pos).starts_with(name)) return differs("another module");
        cursor.pos += name.size();
        const std::span<const float> parameters = string.parameters(i);
        const bool hasList = cursor.pos < cursor.text.size() && cursor.text[cursor.pos] == '(';
        if (parameters.empty() != !hasList) return differs("another parameter count");
        if (!hasList) continue;
        for (size_t p = 0; p < parameters.size(); ++p) {
            ++cursor.pos; // '(' or ','
            double value = 0;
            const char* begin = cursor.text.data() + cursor.pos;
            const auto [end, error] = std::from_chars(begin, cursor.text.data() + cursor.text.size(), value);
            if (error != std::errc()) return differs("a malformed parameter");
            if (!closeEnough(parameters[p], value, tolerance)) return differs("another parameter value");
            cursor.pos += static_cast<size_t>(end - begin);
            const char next = cursor.pos < cursor.text.size() ? cursor.text[cursor.pos] : '\0';
            if (next != (p + 1 < parameters.size() ? ',' : ')')) return differs("another parameter count");
        }
        ++cursor.pos; // ')'
    }
    if (cursor.pos < cursor.text.size())
        return "the text goes on after the derived string's " + std::to_string(string.size()) +
               " modules: " + std::string(cursor.from(cursor.pos)) + "...";
    return std::nullopt;
}

size_t endOfBranch(const ModuleString& string, size_t i) {
    int depth = 0;
    for (; i < string.size(); ++i) {
        if (string.symbols[i] == kPush) ++depth;
        if (string.symbols[i] == kPop && depth-- == 0) return i;
    }
    return i;
}

void computeBracketPartners(const ModuleString& string, std::vector<int32_t>& partners) {
    const size_t n = string.size();
    partners.assign(n, -1);
    std::vector<int32_t> open;
    for (size_t i = 0; i < n; ++i) {
        SymbolId symbol = string.symbols[i];
        if (symbol == kPush) {
            open.push_back(static_cast<int32_t>(i));
        } else if (symbol == kPop && !open.empty()) {
            partners[i] = open.back();
            partners[open.back()] = static_cast<int32_t>(i);
            open.pop_back();
        }
    }
    for (int32_t unclosed : open) partners[unclosed] = static_cast<int32_t>(n);
}

std::map<std::string, size_t> moduleCounts(const ModuleString& string, const SymbolTable& symbols) {
    std::vector<size_t> count(symbols.size(), 0);
    for (SymbolId symbol : string.symbols) ++count[symbol];
    std::map<std::string, size_t> counts;
    for (size_t id = 0; id < count.size(); ++id)
        if (count[id] != 0) counts[symbols.name(static_cast<SymbolId>(id))] = count[id];
    return counts;
}

} // namespace lsys
