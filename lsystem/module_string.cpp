#include "lsystem/module_string.h"

#include <cstdio>

#include "lsystem/memory_budget.h"

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
        std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(parameters[p]));
        out += buffer;
    }
    out += ')';
    return out.size() - before - (parameters.size() - 1);
}

} // namespace

std::string toString(const ModuleString& string, const SymbolTable& symbols) {
    std::string out;
    out.reserve(string.size());
    for (size_t i = 0; i < string.size(); ++i) appendModule(out, string, symbols, i);
    return out;
}

std::string toCpfgString(const ModuleString& string, const SymbolTable& symbols) {
    constexpr size_t kLineLength = 70;
    std::string out;
    out.reserve(string.size() + string.size() / kLineLength + 1);
    size_t onLine = 0;
    for (size_t i = 0; i < string.size(); ++i) {
        if (onLine >= kLineLength) {
            out += '\n';
            onLine = 0;
        }
        onLine += appendModule(out, string, symbols, i);
    }
    out += '\n';
    return out;
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

} // namespace lsys
