// The b-grammar built from the rules, never expanding the word (Calgary
// b-grammar thesis, §4.1, §4.3, §5.1). The word a module becomes in r more
// steps depends only on the module (symbol and parameter bits) and r when the
// rules are context-free and draw no random numbers, so each (module, r) is
// rewritten once: it becomes nothing, a single item (substituted where it is
// used, §4.3), or a node whose body holds what each module of its successor
// becomes in r - 1 steps. A step is derive()'s: the rules, then the
// decomposition rules until none applies (at most their maximum depth); the
// interpretation rules, when asked for, rewrite the modules left after the last
// step the same way. Decomposition and interpretation are context-free here, so
// applying them module by module gives derive()'s passes over the whole string.
//
// With random draws the key gains a variant in [0, k): every occurrence of a
// module picks one from the seed and the occurrence's place in its parent's
// body, and each variant is rewritten with its own random streams (the
// pseudo-stochastic L-systems of §5.1).

#include <algorithm>
#include <string>
#include <unordered_map>

#include "lsystem/common/error.h"
#include "lsystem/common/random.h"
#include "lsystem/instancing/bgrammar_draft.h"
#include "lsystem/rewriting/rewriter.h"

namespace lsys {

namespace {

// Pass numbers of the pseudo-random streams, apart for every step and depth.
constexpr uint64_t kPassesPerStep = 1024;
constexpr uint64_t kInterpretationPass = 1ull << 62;

struct Key {
    uint32_t module = 0;
    int32_t remaining = 0; // steps still to apply
    uint32_t variant = 0;
    friend bool operator==(const Key&, const Key&) = default;
};

struct KeyHash {
    size_t operator()(const Key& key) const {
        return splitmix64((uint64_t{key.module} << 32 | static_cast<uint32_t>(key.remaining)) ^
                          splitmix64(key.variant));
    }
};

// Per symbol: whether rewriting it, or anything it becomes, can draw random numbers.
std::vector<uint8_t> randomSymbols(const Grammar& grammar, bool interpreted) {
    std::vector<const ProductionSet*> sets{&grammar.rules, &grammar.decomposition};
    if (interpreted) sets.push_back(&grammar.interpretation);
    std::vector<uint8_t> random(grammar.symbols.size(), 0);
    for (const ProductionSet* set : sets)
        for (const Production& production : set->productions) random[production.strict.symbol] |= production.usesRandom;
    for (bool changed = true; changed;) {
        changed = false;
        for (const ProductionSet* set : sets)
            for (const Production& production : set->productions) {
                uint8_t& reaches = random[production.strict.symbol];
                for (const SuccessorModule& module : production.successor)
                    if (!reaches && random[module.symbol]) reaches = changed = true;
            }
    }
    return random;
}

bool contextFree(const Grammar& grammar, bool interpreted) {
    return !grammar.rules.contextSensitive && !grammar.decomposition.contextSensitive &&
           !(interpreted && grammar.interpretation.contextSensitive);
}

// Node bodies of a draft, each stored once: rewriting different keys to the
// same word (other parameters, or variants that drew alike) shares one node.
class NodeInterner {
public:
    explicit NodeInterner(BGrammar& draft) : draft_(draft), known_(0, Hash{&draft}, Equal{&draft}) {}

    uint32_t intern(std::span<const BodyItem> body, const BGrammarLimits& limits) {
        const uint32_t candidate = appendNode(draft_, body, limits);
        auto [known, added] = known_.insert(candidate);
        if (!added) {
            draft_.body.resize(draft_.body.size() - body.size());
            draft_.nodes.pop_back();
        }
        return *known;
    }

private:
    struct Hash {
        const BGrammar* draft;
        size_t operator()(uint32_t node) const {
            uint64_t hash = 0;
            for (const BodyItem& item : draft->bodyOf(node))
                hash = splitmix64(hash ^ (uint64_t{item.index} << 1 | item.isNode()));
            return hash;
        }
    };
    struct Equal {
        const BGrammar* draft;
        bool operator()(uint32_t a, uint32_t b) const {
            std::span<const BodyItem> x = draft->bodyOf(a), y = draft->bodyOf(b);
            return std::equal(x.begin(), x.end(), y.begin(), y.end());
        }
    };
    BGrammar& draft_;
    std::unordered_set<uint32_t, Hash, Equal> known_;
};

class MemoisedBuilder {
public:
    MemoisedBuilder(const Grammar& grammar, const BGrammarOptions& options)
        : grammar_(grammar), options_(options), seed_(options.seed.value_or(grammar.seed)),
          random_(randomSymbols(grammar, options.interpreted)), modules_(draft_), nodes_(draft_) {
        draft_.symbolCount = grammar.symbols.size();
        draft_.interpreted = options.interpreted;
        randomness_ = std::find(random_.begin(), random_.end(), 1) != random_.end()
                          ? static_cast<uint32_t>(options.randomness)
                          : 0;
        draft_.method = randomness_ > 0 ? BGrammarMethod::PseudoStochastic : BGrammarMethod::Memoised;
        inert_.assign(grammar.symbols.size(), 1);
        for (const ProductionSet* set : {&grammar.rules, &grammar.decomposition, &grammar.interpretation}) {
            if (set == &grammar.interpretation && !options.interpreted) continue;
            for (const Production& production : set->productions) inert_[production.strict.symbol] = 0;
        }
    }

    BGrammar build() {
        const int steps = std::max(0, options_.steps.value_or(grammar_.derivationLength));
        ModuleString axiom = axiomString(grammar_, seed_);
        if (grammar_.decomposeAxiom) passesToFixpoint(grammar_.decomposition, 1, 0, axiom);
        const uint64_t axiomKey = splitmix64(seed_);
        std::vector<BodyItem> body;
        for (size_t i = 0; i < axiom.size(); ++i) {
            const uint32_t module = modules_.intern(axiom.symbols[i], axiom.parameters(i));
            if (std::optional<BodyItem> item = resolve({module, steps, variantOf(module, axiomKey, i)}))
                body.push_back(*item);
        }
        appendNode(draft_, body, options_.limits);
        return finishBGrammar(std::move(draft_), options_.limits);
    }

private:
    // A module being rewritten: its successor (module indices in successors_)
    // and, in bodies_, the items of its body made so far.
    struct Frame {
        Key key;
        uint64_t streamKey = 0; // its random streams and its children's variants derive from this
        size_t successorBegin = 0, successorEnd = 0, next = 0;
        size_t bodyBegin = 0;
    };

    // What key becomes, depth first with an explicit stack (derivations can be
    // thousands of steps deep): nothing, one item, or a node.
    std::optional<BodyItem> resolve(const Key& root) {
        if (std::optional<std::optional<BodyItem>> known = resolvedWithoutRewriting(root)) return *known;
        push(root);
        for (;;) {
            Frame& frame = frames_.back();
            if (frame.next < frame.successorEnd) {
                const size_t place = frame.next - frame.successorBegin;
                const uint32_t child = successors_[frame.next++];
                const Key key{child, frame.key.remaining - 1, variantOf(child, frame.streamKey, place)};
                if (std::optional<std::optional<BodyItem>> known = resolvedWithoutRewriting(key)) {
                    if (*known) bodies_.push_back(**known);
                } else {
                    push(key);
                }
                continue;
            }
            std::optional<BodyItem> item =
                itemFor({bodies_.data() + frame.bodyBegin, bodies_.size() - frame.bodyBegin});
            memo_.emplace(frame.key, item);
            bodies_.resize(frame.bodyBegin);
            successors_.resize(frame.successorBegin);
            frames_.pop_back();
            if (frames_.empty()) return item;
            if (item) bodies_.push_back(*item);
        }
    }

    // The result when it needs no rewriting: a module no production applies
    // to, the last step, or a key already rewritten.
    std::optional<std::optional<BodyItem>> resolvedWithoutRewriting(const Key& key) {
        const TerminalModule module = draft_.modules[key.module];
        if (inert_[module.symbol]) return BodyItem{BodyItem::Kind::Module, key.module};
        if (auto found = memo_.find(key); found != memo_.end()) return found->second;
        if (key.remaining > 0) return std::nullopt;
        if (!options_.interpreted) return BodyItem{BodyItem::Kind::Module, key.module};
        ModuleString word;
        word.push(module.symbol, draft_.parametersOf(module));
        passesToFixpoint(grammar_.interpretation, kInterpretationPass, streamKeyOf(key), word);
        std::vector<BodyItem> body;
        for (size_t i = 0; i < word.size(); ++i)
            body.push_back({BodyItem::Kind::Module, modules_.intern(word.symbols[i], word.parameters(i))});
        std::optional<BodyItem> item = itemFor(body);
        memo_.emplace(key, item);
        return item;
    }

    // Rewrites key's module one step and opens a frame for it.
    void push(const Key& key) {
        // Keys being rewritten and rewritten ones cost memory like body items
        // (a chain A(x) -> A(x+1) makes neither nodes nor items, only keys).
        if (frames_.size() + memo_.size() >= options_.limits.maxItems)
            throw DerivationError(
                "b-grammar budget exceeded: more than " + std::to_string(options_.limits.maxItems) +
                " (module, step) keys to rewrite (raise it with --max-items, or lower the number of steps)");
        // A memo entry: key, result and the hash table's links; the draft twice for its vectors' growth.
        constexpr uint64_t kKeyBytes = sizeof(Key) + sizeof(std::optional<BodyItem>) + 3 * sizeof(void*);
        need(options_.memory, "b-grammar",
             bytesPlus(bytesTimes(frames_.size() + memo_.size() + 1, kKeyBytes), bytesTimes(byteSize(draft_), 2)));
        const uint64_t streamKey = streamKeyOf(key);
        const uint64_t pass = static_cast<uint64_t>(key.remaining) * kPassesPerStep;
        const TerminalModule module = draft_.modules[key.module];
        ModuleString word;
        rewriteModule(grammar_.rules, module.symbol, draft_.parametersOf(module), {seed_, pass, streamKey}, word);
        passesToFixpoint(grammar_.decomposition, pass + 1, streamKey, word);
        Frame frame{key, streamKey, successors_.size(), 0, 0, bodies_.size()};
        for (size_t i = 0; i < word.size(); ++i)
            successors_.push_back(modules_.intern(word.symbols[i], word.parameters(i)));
        frame.successorEnd = successors_.size();
        frame.next = frame.successorBegin;
        frames_.push_back(frame);
    }

    // derive()'s passes of a decomposition or interpretation set over a word
    // (here the successor of one module), until none applies.
    void passesToFixpoint(const ProductionSet& set, uint64_t firstPass, uint64_t streamKey, ModuleString& word) {
        if (set.empty()) return;
        ModuleString next;
        for (int depth = 0; depth < set.maxDepth; ++depth) {
            next.clear();
            bool applied = false;
            for (size_t i = 0; i < word.size(); ++i)
                applied |=
                    rewriteModule(set, word.symbols[i], word.parameters(i),
                                  {seed_, firstPass + static_cast<uint64_t>(depth), splitmix64(streamKey + i)}, next);
            std::swap(word, next);
            if (word.size() > options_.limits.maxItems)
                throw DerivationError("b-grammar budget exceeded: one module decomposes into more than " +
                                      std::to_string(options_.limits.maxItems) + " modules");
            if (!applied) break;
        }
    }

    // A body of no item is nothing, of one item that item (Calgary b-grammar thesis, §4.3), else a node.
    std::optional<BodyItem> itemFor(std::span<const BodyItem> body) {
        if (body.empty()) return std::nullopt;
        if (body.size() == 1) return body.front();
        return BodyItem{BodyItem::Kind::Node, nodes_.intern(body, options_.limits)};
    }

    uint64_t streamKeyOf(const Key& key) const {
        const TerminalModule& module = draft_.modules[key.module];
        const uint64_t content = hashModule(module.symbol, draft_.parametersOf(module));
        return splitmix64(content ^ splitmix64(static_cast<uint64_t>(key.remaining) ^ splitmix64(seed_ + key.variant)));
    }

    // The variant an occurrence of a module rewrites as: always 0 without
    // random draws below it, so deterministic parts are shared fully.
    uint32_t variantOf(uint32_t module, uint64_t parentStreamKey, size_t place) const {
        if (randomness_ == 0 || !random_[draft_.modules[module].symbol]) return 0;
        return static_cast<uint32_t>(splitmix64(parentStreamKey ^ splitmix64(place)) % randomness_);
    }

    const Grammar& grammar_;
    const BGrammarOptions& options_;
    uint64_t seed_;
    std::vector<uint8_t> random_; // per symbol, from randomSymbols()
    std::vector<uint8_t> inert_;  // per symbol: no production at all, the module stays as it is
    uint32_t randomness_ = 0;     // k, 0 when no production draws
    BGrammar draft_;
    ModuleInterner modules_;
    NodeInterner nodes_;
    std::unordered_map<Key, std::optional<BodyItem>, KeyHash> memo_;
    std::vector<Frame> frames_;
    std::vector<uint32_t> successors_;
    std::vector<BodyItem> bodies_;
};

} // namespace

bool memoisable(const Grammar& grammar, const BGrammarOptions& options) {
    if (!contextFree(grammar, options.interpreted) || producedCut(grammar) || grammar.sequential || grammar.queries)
        return false;
    if (options.randomness > 0) return true;
    std::vector<uint8_t> random = randomSymbols(grammar, options.interpreted);
    return std::find(random.begin(), random.end(), 1) == random.end();
}

BGrammar memoisedBGrammar(const Grammar& grammar, const BGrammarOptions& options) {
    return MemoisedBuilder(grammar, options).build();
}

} // namespace lsys
