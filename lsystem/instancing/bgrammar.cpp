#include "lsystem/instancing/bgrammar.h"

#include <new>
#include <string>

#include "lsystem/common/error.h"
#include "lsystem/instancing/bgrammar_draft.h"
#include "lsystem/instancing/sequitur.h"
#include "lsystem/rewriting/rewriter.h"

namespace lsys {

namespace {

BGrammar buildUnguarded(const Grammar& grammar, const BGrammarOptions& options) {
    if (memoisable(grammar, options)) return memoisedBGrammar(grammar, options);
    DeriveOptions derivation;
    derivation.steps = options.steps;
    derivation.seed = options.seed;
    derivation.maxModules = options.maxModules;
    derivation.memory = options.memory;
    derivation.onStep = options.onStep;
    ModuleString word = derive(grammar, derivation);
    if (options.interpreted) word = applyInterpretation(grammar, word, derivation);
    need(options.memory, "b-grammar", bytesPlus(moduleStringBytes(word), compressionBytes(word)));
    BGrammar compressed = compressWord(word, grammar.symbols.size(), options.limits);
    compressed.interpreted = options.interpreted;
    return compressed;
}

} // namespace

BGrammar buildBGrammar(const Grammar& grammar, const BGrammarOptions& options) {
    // Running out of memory below the budgets is reported like a budget, as derive() does.
    try {
        return buildUnguarded(grammar, options);
    } catch (const std::bad_alloc&) {
        throw DerivationError(
            "out of memory while building the b-grammar (lower --max-nodes / --max-items or the number of steps)");
    }
}

ModuleString expand(const BGrammar& grammar, size_t maxModules) {
    ModuleString word;
    if (grammar.nodes.empty()) return word;
    if (grammar.nodes.back().modules > maxModules)
        throw DerivationError("expanding the b-grammar would give " + std::to_string(grammar.nodes.back().modules) +
                              " modules, more than the budget of " + std::to_string(maxModules));
    struct Position {
        uint32_t node;
        uint32_t next; // index in the node's body
    };
    std::vector<Position> stack{{grammar.axiom(), 0}};
    while (!stack.empty()) {
        Position& top = stack.back();
        std::span<const BodyItem> body = grammar.bodyOf(top.node);
        if (top.next == body.size()) {
            stack.pop_back();
            continue;
        }
        const BodyItem item = body[top.next++];
        if (item.isNode()) {
            stack.push_back({item.index, 0});
        } else {
            const TerminalModule& module = grammar.modules[item.index];
            word.push(module.symbol, grammar.parametersOf(module));
        }
    }
    return word;
}

std::vector<uint64_t> countModules(const BGrammar& grammar) {
    std::vector<uint64_t> counts(grammar.symbolCount, 0);
    if (grammar.nodes.empty()) return counts;
    for (const SymbolCount& count : grammar.countsOf(grammar.axiom())) counts[count.symbol] = count.count;
    return counts;
}

uint64_t nodeReferences(const BGrammar& grammar) {
    uint64_t references = 0;
    for (const BodyItem& item : grammar.body) references += item.isNode();
    return references;
}

size_t byteSize(const BGrammar& grammar) {
    return grammar.nodes.size() * sizeof(BNode) + grammar.body.size() * sizeof(BodyItem) +
           grammar.modules.size() * sizeof(TerminalModule) + grammar.params.size() * sizeof(float) +
           grammar.counts.size() * sizeof(SymbolCount) + sizeof(BGrammar);
}

} // namespace lsys
