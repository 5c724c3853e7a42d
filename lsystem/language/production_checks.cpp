#include "lsystem/language/production_checks.h"

#include <cmath>
#include <cstdio>
#include <optional>

namespace lsys {

void formStochasticGroups(ProductionSet& set, std::span<const std::string> signatures, const std::string& file,
                          std::vector<Diagnostic>& diagnostics) {
    std::vector<Production>& productions = set.productions;
    for (size_t i = 0; i < productions.size();) {
        if (!productions[i].stochastic) {
            ++i;
            continue;
        }
        size_t end = i + 1;
        double sum = productions[i].probability;
        while (end < productions.size() && productions[end].stochastic && signatures[end] == signatures[i]) {
            sum += productions[end].probability;
            productions[end].groupSize = 0;
            ++end;
        }
        productions[i].groupSize = static_cast<uint32_t>(end - i);
        if (std::fabs(sum - 1.0) > 1e-6) {
            char text[64];
            std::snprintf(text, sizeof text, "%.9g", sum);
            diagnostics.push_back({file, productions[i].line, 1,
                                   "probabilities of the stochastic group for '" + signatures[i] + "' sum to " + text,
                                   "a sum of 1 over consecutive productions with the same predecessor"});
        }
        i = end;
    }
}

void warnOfUnbalancedBrackets(const ProductionSet& set, const std::string& file, std::vector<Diagnostic>& warnings) {
    for (const Production& production : set.productions) {
        int opened = 0, closed = 0;
        for (const SuccessorModule& module : production.successor) {
            opened += module.symbol == kPush;
            closed += module.symbol == kPop;
        }
        int replaced = (production.strict.symbol == kPush) - (production.strict.symbol == kPop);
        for (const PatternModule& module : production.strictTail)
            replaced += (module.symbol == kPush) - (module.symbol == kPop);
        if (opened - closed != replaced)
            warnings.push_back({file,
                                production.line,
                                1,
                                "the successor's brackets do not balance (" + std::to_string(opened) + " '[' and " +
                                    std::to_string(closed) + " ']')",
                                {},
                                {},
                                Severity::Warning});
    }
}

void warnOfCpfgAtModules(const Grammar& grammar, const ProductionSet& set, const std::string& file,
                         std::vector<Diagnostic>& warnings) {
    if (!grammar.style.cpfgModules) return;
    for (const Production& production : set.productions) {
        std::vector<SymbolId> replaced{production.strict.symbol};
        for (const PatternModule& module : production.strictTail) replaced.push_back(module.symbol);
        for (SymbolId symbol : replaced) {
            const std::string& name = grammar.symbols.name(symbol);
            if (name.empty() || name[0] == '@' || !grammar.symbols.find("@" + name)) continue;
            warnings.push_back({file,
                                production.line,
                                1,
                                "cpfg reads '@" + name + "' as two modules, '@' and '" + name +
                                    "', so in cpfg this production also rewrites the '" + name + "' of every '@" +
                                    name + "'; here '@" + name + "' is one module, which it leaves alone",
                                {},
                                {},
                                Severity::Warning});
        }
    }
}

void warnOfCpfgSubLsystems(const Grammar& grammar, const ProductionSet& set, const std::string& file,
                           std::vector<Diagnostic>& warnings) {
    const std::optional<SymbolId> question = grammar.symbols.find("?");
    if (!grammar.style.cpfgModules || !question) return;
    for (const Production& production : set.productions)
        for (const SuccessorModule& module : production.successor)
            if (module.symbol == *question && !module.arguments.empty()) {
                warnings.push_back({file,
                                    production.line,
                                    1,
                                    "cpfg's sub-L-systems ('?(n, s)' ... '$') are not supported: this production's "
                                    "'?(...)' is read as an ordinary module, which no other L-system rewrites",
                                    {},
                                    {},
                                    Severity::Warning});
                break;
            }
}

} // namespace lsys
