#include "lsystem/language/grammar.h"

#include "lsystem/language/query_modules.h"

namespace lsys {

namespace {

bool drawsRandom(const Expression& expression) {
    for (const Instruction& instruction : expression.code)
        if (instruction.op == Op::Ran || instruction.op == Op::NRan) return true;
    return false;
}

void index(ProductionSet& set, size_t symbolCount) {
    set.bySymbol.assign(symbolCount, {});
    set.producesParameters = false;
    set.contextSensitive = false;
    set.consumesSeveral = false;
    for (size_t i = 0; i < set.productions.size(); ++i) {
        Production& production = set.productions[i];
        production.usesRandom = production.groupSize > 1 || !production.before.empty() || !production.after.empty() ||
                                (production.condition && drawsRandom(*production.condition));
        for (const SuccessorModule& module : production.successor) {
            set.producesParameters |= !module.arguments.empty();
            for (const Expression& argument : module.arguments) production.usesRandom |= drawsRandom(argument);
        }
        set.contextSensitive |= !production.left.empty() || !production.right.empty() || !production.strictTail.empty();
        set.consumesSeveral |= !production.strictTail.empty();
        if (production.groupSize > 0) set.bySymbol[production.strict.symbol].push_back(static_cast<uint32_t>(i));
    }
    // An alternative of a stochastic group draws if any alternative does: the leader decides for all.
    for (size_t i = 0; i < set.productions.size(); ++i)
        for (uint32_t k = 1; k < set.productions[i].groupSize; ++k)
            set.productions[i].usesRandom |= set.productions[i + k].usesRandom;
}

bool sequential(const Grammar& grammar) {
    if (!grammar.globals.variables.empty()) return true;
    for (const Block* block : {&grammar.startBlock, &grammar.startEachBlock, &grammar.endEachBlock, &grammar.endBlock})
        if (!block->empty()) return true;
    for (const SuccessorModule& module : grammar.axiom)
        for (const Expression& argument : module.arguments)
            if (hasSideEffects(argument)) return true;
    for (const ProductionSet* set : {&grammar.rules, &grammar.decomposition, &grammar.interpretation})
        for (const Production& production : set->productions) {
            if (!production.before.empty() || !production.after.empty()) return true;
            if (production.condition && hasSideEffects(*production.condition)) return true;
            for (const SuccessorModule& module : production.successor)
                for (const Expression& argument : module.arguments)
                    if (hasSideEffects(argument)) return true;
        }
    return false;
}

} // namespace

void finalizeGrammar(Grammar& grammar) {
    index(grammar.rules, grammar.symbols.size());
    index(grammar.decomposition, grammar.symbols.size());
    index(grammar.interpretation, grammar.symbols.size());
    grammar.ignored.resize(grammar.symbols.size(), 0);
    grammar.localCount = 0;
    for (ProductionSet* set : {&grammar.rules, &grammar.decomposition, &grammar.interpretation})
        for (Production& production : set->productions) {
            production.firstLocal = grammar.localCount;
            grammar.localCount += static_cast<uint32_t>(production.variables.size() - production.formalCount);
        }
    grammar.sequential = sequential(grammar);
    grammar.queries = hasQueries(grammar);
}

} // namespace lsys
