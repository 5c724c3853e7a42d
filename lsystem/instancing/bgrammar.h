#pragma once
// The b-grammar (Calgary b-grammar thesis, ch. 4-6): an acyclic grammar that
// generates exactly one word, the derived string of an L-system, without
// storing it. Every non-terminal (a node) has one production, its body:
// terminal modules with their parameters and references to other nodes, in
// string order. Nodes are stored in topological order, children before parents,
// and the axiom is the last node, so one forward pass over the nodes sees every
// node after all the nodes it refers to.
//
// This is the grammar side of the InstanceGraph: each node becomes an object,
// each reference in a body an instance of it whose transform is the turtle's
// state accumulated over the body before it (the thesis, §4.2). Bodies are kept
// plain to walk for that, and every node caches what the instancing step and
// the counts need: the length of its expansion, its modules per symbol and its
// bracket depth effect.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lsystem/common/memory_budget.h"
#include "lsystem/language/grammar.h"
#include "lsystem/language/module_string.h"

namespace lsys {

// A terminal module of a body: its symbol and parameters. Equal modules
// (same symbol, same parameter bits) are stored once and shared by index.
struct TerminalModule {
    SymbolId symbol = 0;
    uint16_t paramCount = 0;
    uint32_t paramStart = 0; // into BGrammar::params
};

// One entry of a body: a terminal module or a reference to a node.
struct BodyItem {
    enum class Kind : uint8_t { Module, Node };
    Kind kind = Kind::Module;
    uint32_t index = 0; // into BGrammar::modules or BGrammar::nodes

    bool isNode() const { return kind == Kind::Node; }
    friend bool operator==(const BodyItem&, const BodyItem&) = default;
};

struct SymbolCount {
    SymbolId symbol = 0;
    uint64_t count = 0;
};

struct BNode {
    uint32_t bodyStart = 0; // into BGrammar::body
    uint32_t bodyLength = 0;
    uint32_t countStart = 0; // into BGrammar::counts: modules per symbol of the expansion, by symbol
    uint32_t countLength = 0;
    uint64_t modules = 0; // length of the expansion
    // Brackets of the expansion: '[' minus ']' over all of it, and the lowest
    // depth any prefix reaches relative to the start (0 or negative). A node is
    // legal (Calgary b-grammar thesis, §4.2: its turtle status function exists)
    // when that is 0: it may leave states pushed but never pops below its start.
    int32_t depthChange = 0;
    int32_t lowestDepth = 0;

    bool legal() const { return lowestDepth == 0; }
};

// How a b-grammar was obtained from its L-system.
enum class BGrammarMethod : uint8_t {
    Memoised,         // from the rules, shared by (module, remaining steps): the exact word (§4.1, §4.3)
    PseudoStochastic, // as Memoised with at most k rewrites per key (§5.1): NOT derive()'s word
    Compressed,       // derived, then compressed by SEQUITUR with bracket legality (ch. 6): the exact word
};

struct BGrammar {
    std::vector<BNode> nodes;   // topological, children first; the axiom is the last
    std::vector<BodyItem> body; // the bodies of all nodes, back to back
    std::vector<TerminalModule> modules;
    std::vector<float> params;
    std::vector<SymbolCount> counts; // per node, sorted by symbol
    size_t symbolCount = 0;          // of the grammar's SymbolTable
    BGrammarMethod method = BGrammarMethod::Memoised;
    bool interpreted = false; // the word includes the interpretation rules

    uint32_t axiom() const { return static_cast<uint32_t>(nodes.size() - 1); }
    std::span<const BodyItem> bodyOf(uint32_t node) const {
        return {body.data() + nodes[node].bodyStart, nodes[node].bodyLength};
    }
    std::span<const SymbolCount> countsOf(uint32_t node) const {
        return {counts.data() + nodes[node].countStart, nodes[node].countLength};
    }
    std::span<const float> parametersOf(const TerminalModule& module) const {
        return {params.data() + module.paramStart, module.paramCount};
    }
};

// Checked while building (when nodes later inlined still count) and after.
struct BGrammarLimits {
    size_t maxNodes = 1'000'000;  // non-terminals plus the axiom
    size_t maxItems = 50'000'000; // entries of all bodies together (also: keys a memoised build rewrites)
};

struct BGrammarOptions {
    std::optional<int> steps;     // default: the grammar's derivation length
    std::optional<uint64_t> seed; // default: the grammar's seed
    // false: the word derive() produces; true: applyInterpretation(derive()),
    // the word the turtle reads.
    bool interpreted = false;
    // The randomness factor k (Calgary b-grammar thesis, §5.1) for productions that draw random
    // numbers: at most k distinct rewrites per (module, remaining steps), each
    // occurrence picking one from the seed. The word then has derive()'s
    // statistics but is not derive()'s word. 0: the exact word, derived and
    // compressed (random streams depend on positions in the string, so equal
    // modules are not rewritten alike and nothing can be shared by key).
    int randomness = 0;
    BGrammarLimits limits;
    size_t maxModules = 50'000'000; // module budget of the derivation when the word is derived first
    // The derivation's strings, the keys a memoised build rewrites and the
    // draft, or SEQUITUR's grammar of a derived word (stage "b-grammar").
    MemoryBudget memory = machineMemoryBudget();
    // As DeriveOptions::onStep, when the word is derived first.
    std::function<void(int, int, size_t)> onStep;
};

// The b-grammar of the grammar's derivation, without expanding the word when
// the grammar allows it: memoised for context-free deterministic rules,
// pseudo-stochastic with options.randomness > 0 for rules that draw random
// numbers; otherwise (contexts, a produced '%' cut, random rules with k = 0)
// the word is derived and compressed (sequitur.h). Throws DerivationError when
// a budget is exceeded.
BGrammar buildBGrammar(const Grammar& grammar, const BGrammarOptions& options = {});

// The word the b-grammar generates. Throws DerivationError past maxModules.
ModuleString expand(const BGrammar& grammar, size_t maxModules = 50'000'000);

// Modules of the word per symbol (indexed by SymbolId), without expanding it.
std::vector<uint64_t> countModules(const BGrammar& grammar);

// References to nodes over all bodies (the instances of the Calgary b-grammar
// thesis, §4.2, the axiom's included).
uint64_t nodeReferences(const BGrammar& grammar);

// Memory the b-grammar occupies (its arrays' sizes, not their capacities).
size_t byteSize(const BGrammar& grammar);

} // namespace lsys
