#include "lsystem/language/query_modules.h"

#include <array>

namespace lsys {

namespace {

// The queried vectors' modules, in the order of queryKinds' indices.
constexpr std::array<const char*, 4> kQueryNames = {"P", "H", "L", "U"};

bool holdsQuery(const std::vector<SuccessorModule>& modules, SymbolId question, const std::vector<uint8_t>& kinds) {
    for (size_t i = 0; i + 1 < modules.size(); ++i)
        if (modules[i].symbol == question && kinds[modules[i + 1].symbol]) return true;
    return false;
}

} // namespace

std::vector<uint8_t> queryKinds(const SymbolTable& symbols) {
    std::vector<uint8_t> kinds(symbols.size(), 0);
    for (size_t k = 0; k < kQueryNames.size(); ++k)
        if (std::optional<SymbolId> id = symbols.find(kQueryNames[k])) kinds[*id] = static_cast<uint8_t>(k + 1);
    return kinds;
}

bool hasQueries(const Grammar& grammar) {
    const std::optional<SymbolId> question = grammar.symbols.find("?");
    if (!question) return false;
    const std::vector<uint8_t> kinds = queryKinds(grammar.symbols);
    if (holdsQuery(grammar.axiom, *question, kinds)) return true;
    for (const ProductionSet* set : {&grammar.rules, &grammar.decomposition})
        for (const Production& production : set->productions)
            if (holdsQuery(production.successor, *question, kinds)) return true;
    return false;
}

} // namespace lsys
