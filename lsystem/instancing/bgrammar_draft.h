#pragma once
// Building blocks shared by the b-grammar builders (memoised from the rules,
// compressed from a derived word). A builder fills a draft: modules, params,
// and nodes with bodies only, children before parents, the axiom last; then
// finishBGrammar() turns it into a BGrammar.

#include <cstdint>
#include <span>
#include <unordered_set>

#include "lsystem/instancing/bgrammar.h"

namespace lsys {

// A hash of a module's symbol and parameter bits.
uint64_t hashModule(SymbolId symbol, std::span<const float> parameters);

// Stores each distinct module (symbol and parameter bits) of a draft once.
class ModuleInterner {
public:
    explicit ModuleInterner(BGrammar& draft) : draft_(draft), known_(0, Hash{&draft}, Equal{&draft}) {}
    uint32_t intern(SymbolId symbol, std::span<const float> parameters);

private:
    struct Hash {
        const BGrammar* draft;
        size_t operator()(uint32_t module) const;
    };
    struct Equal {
        const BGrammar* draft;
        bool operator()(uint32_t a, uint32_t b) const;
    };
    BGrammar& draft_;
    std::unordered_set<uint32_t, Hash, Equal> known_;
};

// Appends a node with the given body to a draft, checking the limits; returns its index.
uint32_t appendNode(BGrammar& draft, std::span<const BodyItem> body, const BGrammarLimits& limits);

// Finishes a draft: nodes referenced once are inlined into their parent
// (Calgary b-grammar thesis, §4.4), so are illegal nodes (those that pop below
// their start) wherever they are used, and unreferenced nodes and modules are
// dropped; then every node's counts and bracket depths are cached. Throws
// DerivationError past the limits or when a count passes 2^64.
BGrammar finishBGrammar(BGrammar draft, const BGrammarLimits& limits);

// Whether buildBGrammar can build the grammar's b-grammar from its rules
// (bgrammar_memoised.cpp), and that builder.
bool memoisable(const Grammar& grammar, const BGrammarOptions& options);
BGrammar memoisedBGrammar(const Grammar& grammar, const BGrammarOptions& options);

} // namespace lsys
