#include "lsystem/instancing/bgrammar_draft.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "lsystem/common/error.h"
#include "lsystem/common/random.h"

namespace lsys {

uint64_t hashModule(SymbolId symbol, std::span<const float> parameters) {
    uint64_t hash = splitmix64(symbol);
    for (float parameter : parameters) {
        uint32_t bits;
        std::memcpy(&bits, &parameter, sizeof bits);
        hash = splitmix64(hash ^ bits);
    }
    return hash;
}

size_t ModuleInterner::Hash::operator()(uint32_t module) const {
    const TerminalModule& m = draft->modules[module];
    return hashModule(m.symbol, draft->parametersOf(m));
}

bool ModuleInterner::Equal::operator()(uint32_t a, uint32_t b) const {
    const TerminalModule& x = draft->modules[a];
    const TerminalModule& y = draft->modules[b];
    // Bits, not values: -0 and 0 print differently, and NaN must equal itself.
    // No parameters: params may still be empty, and memcmp of its null data is undefined.
    return x.symbol == y.symbol && x.paramCount == y.paramCount &&
           (x.paramCount == 0 || std::memcmp(draft->params.data() + x.paramStart, draft->params.data() + y.paramStart,
                                             x.paramCount * sizeof(float)) == 0);
}

uint32_t ModuleInterner::intern(SymbolId symbol, std::span<const float> parameters) {
    if (parameters.size() > std::numeric_limits<uint16_t>::max())
        throw DerivationError("a module has more than 65535 parameters");
    // The module is appended as a candidate and taken back if it is already known.
    draft_.modules.push_back(
        {symbol, static_cast<uint16_t>(parameters.size()), static_cast<uint32_t>(draft_.params.size())});
    draft_.params.insert(draft_.params.end(), parameters.begin(), parameters.end());
    auto [known, added] = known_.insert(static_cast<uint32_t>(draft_.modules.size() - 1));
    if (!added) {
        draft_.modules.pop_back();
        draft_.params.resize(draft_.params.size() - parameters.size());
    }
    return *known;
}

namespace {

[[noreturn]] void limitExceeded(const std::string& what, size_t limit) {
    throw DerivationError("b-grammar budget exceeded: more than " + std::to_string(limit) + " " + what +
                          " (raise it with --max-nodes / --max-items, or lower the number of steps)");
}

struct Depths {
    int32_t change = 0;
    int32_t lowest = 0;
};

// Bracket depths of a body whose referenced nodes already have theirs.
Depths depthsOf(std::span<const BodyItem> body, const BGrammar& grammar, const std::vector<Depths>& nodeDepths) {
    Depths depths;
    for (const BodyItem& item : body) {
        if (item.isNode()) {
            depths.lowest = std::min(depths.lowest, depths.change + nodeDepths[item.index].lowest);
            depths.change += nodeDepths[item.index].change;
            continue;
        }
        const SymbolId symbol = grammar.modules[item.index].symbol;
        if (symbol == kPush) ++depths.change;
        if (symbol == kPop) depths.lowest = std::min(depths.lowest, --depths.change);
    }
    return depths;
}

uint64_t checkedAdd(uint64_t a, uint64_t b) {
    uint64_t sum;
    if (__builtin_add_overflow(a, b, &sum)) throw DerivationError("the b-grammar generates more than 2^64 modules");
    return sum;
}

// Drops the modules no body uses and renumbers the rest.
void dropUnusedModules(BGrammar& grammar) {
    constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> newIndex(grammar.modules.size(), kUnused);
    for (const BodyItem& item : grammar.body)
        if (!item.isNode()) newIndex[item.index] = 0;
    std::vector<TerminalModule> modules;
    std::vector<float> params;
    for (size_t m = 0; m < grammar.modules.size(); ++m) {
        if (newIndex[m] == kUnused) continue;
        newIndex[m] = static_cast<uint32_t>(modules.size());
        TerminalModule module = grammar.modules[m];
        std::span<const float> parameters = grammar.parametersOf(module);
        module.paramStart = static_cast<uint32_t>(params.size());
        params.insert(params.end(), parameters.begin(), parameters.end());
        modules.push_back(module);
    }
    for (BodyItem& item : grammar.body)
        if (!item.isNode()) item.index = newIndex[item.index];
    grammar.modules = std::move(modules);
    grammar.params = std::move(params);
}

// Per node: the length of its expansion and its modules per symbol.
void cacheCounts(BGrammar& grammar) {
    std::vector<uint64_t> perSymbol(grammar.symbolCount, 0);
    std::vector<SymbolId> present;
    auto add = [&](SymbolId symbol, uint64_t count) {
        if (perSymbol[symbol] == 0) present.push_back(symbol);
        perSymbol[symbol] = checkedAdd(perSymbol[symbol], count);
    };
    for (uint32_t node = 0; node < grammar.nodes.size(); ++node) {
        for (const BodyItem& item : grammar.bodyOf(node)) {
            if (!item.isNode()) {
                add(grammar.modules[item.index].symbol, 1);
                continue;
            }
            for (const SymbolCount& count : grammar.countsOf(item.index)) add(count.symbol, count.count);
        }
        std::sort(present.begin(), present.end());
        BNode& target = grammar.nodes[node];
        target.countStart = static_cast<uint32_t>(grammar.counts.size());
        target.countLength = static_cast<uint32_t>(present.size());
        target.modules = 0;
        for (SymbolId symbol : present) {
            grammar.counts.push_back({symbol, perSymbol[symbol]});
            target.modules = checkedAdd(target.modules, perSymbol[symbol]);
            perSymbol[symbol] = 0;
        }
        present.clear();
    }
}

} // namespace

uint32_t appendNode(BGrammar& draft, std::span<const BodyItem> body, const BGrammarLimits& limits) {
    if (draft.nodes.size() >= limits.maxNodes) limitExceeded("nodes", limits.maxNodes);
    if (draft.body.size() + body.size() > limits.maxItems) limitExceeded("body items", limits.maxItems);
    BNode node;
    node.bodyStart = static_cast<uint32_t>(draft.body.size());
    node.bodyLength = static_cast<uint32_t>(body.size());
    draft.body.insert(draft.body.end(), body.begin(), body.end());
    draft.nodes.push_back(node);
    return static_cast<uint32_t>(draft.nodes.size() - 1);
}

BGrammar finishBGrammar(BGrammar draft, const BGrammarLimits& limits) {
    constexpr uint32_t kInlined = std::numeric_limits<uint32_t>::max();
    const uint32_t count = static_cast<uint32_t>(draft.nodes.size());
    const uint32_t axiom = count - 1;
    std::vector<uint32_t> uses(count, 0);
    for (const BodyItem& item : draft.body)
        if (item.isNode()) ++uses[item.index];

    BGrammar finished;
    finished.symbolCount = draft.symbolCount;
    finished.method = draft.method;
    finished.interpreted = draft.interpreted;
    finished.modules = std::move(draft.modules);
    finished.params = std::move(draft.params);

    // The new body of every node, kept or inlined, as a range of rewritten;
    // a kept node's references already carry the new indices of their targets.
    std::vector<BodyItem> rewritten;
    std::vector<std::pair<size_t, size_t>> range(count);
    std::vector<uint32_t> newIndex(count, kInlined);
    std::vector<Depths> depths(count);
    std::vector<Depths> keptDepths;
    size_t keptItems = 0;
    for (uint32_t node = 0; node < count; ++node) {
        if (uses[node] == 0 && node != axiom) continue; // unreachable
        const size_t start = rewritten.size();
        for (const BodyItem& item : draft.bodyOf(node)) {
            if (!item.isNode()) {
                rewritten.push_back(item);
            } else if (newIndex[item.index] != kInlined) {
                rewritten.push_back({BodyItem::Kind::Node, newIndex[item.index]});
            } else {
                for (size_t k = range[item.index].first; k < range[item.index].second; ++k) {
                    const BodyItem copy = rewritten[k];
                    rewritten.push_back(copy);
                }
            }
        }
        range[node] = {start, rewritten.size()};
        depths[node] = depthsOf({rewritten.data() + start, rewritten.size() - start}, finished, keptDepths);
        const bool keep = node == axiom || (uses[node] > 1 && depths[node].lowest == 0);
        if (!keep) continue;
        keptItems += rewritten.size() - start;
        if (keptItems > limits.maxItems) limitExceeded("body items", limits.maxItems);
        newIndex[node] = static_cast<uint32_t>(keptDepths.size());
        keptDepths.push_back(depths[node]);
    }

    for (uint32_t node = 0; node < count; ++node) {
        if (newIndex[node] == kInlined) continue;
        BNode kept;
        kept.bodyStart = static_cast<uint32_t>(finished.body.size());
        kept.bodyLength = static_cast<uint32_t>(range[node].second - range[node].first);
        kept.depthChange = depths[node].change;
        kept.lowestDepth = depths[node].lowest;
        finished.body.insert(finished.body.end(), rewritten.begin() + static_cast<ptrdiff_t>(range[node].first),
                             rewritten.begin() + static_cast<ptrdiff_t>(range[node].second));
        finished.nodes.push_back(kept);
    }
    dropUnusedModules(finished);
    cacheCounts(finished);
    return finished;
}

} // namespace lsys
