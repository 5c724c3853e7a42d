#pragma once
// The derived word as a structure of arrays: one symbol id per module, and the
// parameters of all modules packed in one float array. A word in which no
// module has parameters stores no offsets at all, which halves the memory
// traffic of plain D0L systems.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lsystem/language/buffer.h"
#include "lsystem/language/symbols.h"

namespace lsys {

struct ModuleString {
    Buffer<SymbolId> symbols;
    // Empty when no module has parameters; otherwise size()+1 entries and the
    // parameters of module i are params[paramStart[i] .. paramStart[i+1]).
    Buffer<uint32_t> paramStart;
    Buffer<float> params;

    size_t size() const { return symbols.size(); }
    bool empty() const { return symbols.empty(); }
    bool hasParameters() const { return !paramStart.empty(); }
    uint32_t paramCount(size_t i) const { return paramStart.empty() ? 0 : paramStart[i + 1] - paramStart[i]; }
    const float* paramData(size_t i) const { return params.data() + (paramStart.empty() ? 0 : paramStart[i]); }
    std::span<const float> parameters(size_t i) const { return {paramData(i), paramCount(i)}; }

    void clear();
    void push(SymbolId symbol, std::span<const float> parameters = {});
    // Switches to the representation with offsets (all modules so far without parameters).
    void addOffsets();
};

// The bytes of a ModuleString of `modules` modules holding `parameters`
// parameters, with offsets or without (saturating; lsystem/common/memory_budget.h).
uint64_t moduleStringBytes(uint64_t modules, uint64_t parameters, bool offsets);
inline uint64_t moduleStringBytes(const ModuleString& string) {
    return moduleStringBytes(string.size(), string.params.size(), string.hasParameters());
}

// Canonical text: modules back to back, parameters printed with %g joined by commas: F(1,0.5)[+A(2)]
std::string toString(const ModuleString& string, const SymbolTable& symbols);
// The same text laid out as cpfg writes a string file (its -str option), for
// comparing derivations with it: a line break before a module once 70
// characters are on the line (its commas uncounted, as cpfg counts), and one
// at the end.
std::string toCpfgString(const ModuleString& string, const SymbolTable& symbols);

enum class TextLayout { OneLine, Cpfg };
// The text of toString or toCpfgString handed to `write` a megabyte at a
// time, so that a long string is written without being held whole.
void writeText(const ModuleString& string, const SymbolTable& symbols, TextLayout layout,
               const std::function<void(std::string_view)>& write);

// Where `text` — a string as toString or toCpfgString write it, or as cpfg
// writes one (line breaks are ignored) — first differs from `string`, module
// for module, parameters compared within `tolerance` relative (1e-6 absolute
// near 0); nullopt when they agree. The message names the module's index and
// both sides.
std::optional<std::string> firstDifference(const ModuleString& string, const SymbolTable& symbols,
                                           std::string_view text, double tolerance = 1e-4);

// How many modules of each name the string holds, by name; names it does
// not hold are left out (`lsys derive --json`'s counts).
std::map<std::string, size_t> moduleCounts(const ModuleString& string, const SymbolTable& symbols);

// Index of the ']' closing the branch that contains position i, or size()
// when none does: where a cut ('%') at i - 1 stops.
size_t endOfBranch(const ModuleString& string, size_t i);

// Index of the matching bracket for every '[' and ']'; -1 for other modules and
// for an unmatched ']'; size() for an unclosed '['.
void computeBracketPartners(const ModuleString& string, std::vector<int32_t>& partners);

} // namespace lsys
