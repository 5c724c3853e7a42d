#include "lsystem/instancing/sequitur.h"

#include <algorithm>
#include <limits>
#include <string>
#include <unordered_map>

#include "lsystem/common/error.h"
#include "lsystem/instancing/bgrammar_draft.h"

namespace lsys {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
// Symbol values: a terminal is its module index; the high bits mark a
// reference to a rule and a rule's guard (the sentinel closing its circular list).
constexpr uint32_t kRuleBit = 1u << 30;
constexpr uint32_t kGuardBit = 1u << 31;

// The brackets of a symbol's expansion (see BNode::depthChange / lowestDepth).
struct Shape {
    int32_t change = 0;
    int32_t lowest = 0;
    bool opensBranch = false; // the expansion starts with '['
};

Shape concatenate(const Shape& a, const Shape& b) {
    return {a.change + b.change, std::min(a.lowest, a.change + b.lowest), a.opensBranch};
}

// The legality rule of sequitur.h.
bool mayBecomeRule(const Shape& a, const Shape& b) {
    const Shape joined = concatenate(a, b);
    return joined.lowest >= 0 && (joined.change == 0 || a.opensBranch);
}

class Sequitur {
public:
    explicit Sequitur(std::vector<Shape> terminals) : terminals_(std::move(terminals)) { newRule({}); }

    void append(uint32_t terminal) {
        insertAfter(last(kAxiomRule), newSymbol(terminal));
        check(symbols_[last(kAxiomRule)].prev);
    }

    // The rules as nodes of draft, children first, the axiom last.
    void writeNodes(BGrammar& draft, const BGrammarLimits& limits) const {
        std::vector<uint32_t> nodeOf(rules_.size(), kNone);
        std::vector<std::pair<uint32_t, uint32_t>> stack{{kAxiomRule, first(kAxiomRule)}}; // rule, next symbol to visit
        std::vector<BodyItem> body;
        while (!stack.empty()) {
            auto& [rule, cursor] = stack.back();
            if (cursor == rules_[rule].guard) {
                body.clear();
                for (uint32_t s = first(rule); s != rules_[rule].guard; s = symbols_[s].next) {
                    const uint32_t value = symbols_[s].value;
                    body.push_back(isRuleReference(value) ? BodyItem{BodyItem::Kind::Node, nodeOf[value & ~kRuleBit]}
                                                          : BodyItem{BodyItem::Kind::Module, value});
                }
                nodeOf[rule] = appendNode(draft, body, limits);
                stack.pop_back();
                continue;
            }
            const uint32_t value = symbols_[cursor].value;
            cursor = symbols_[cursor].next;
            if (isRuleReference(value) && nodeOf[value & ~kRuleBit] == kNone)
                stack.push_back({value & ~kRuleBit, first(value & ~kRuleBit)});
        }
    }

private:
    static constexpr uint32_t kAxiomRule = 0;

    struct Symbol {
        uint32_t value = 0;
        uint32_t prev = kNone, next = kNone;
    };
    struct Rule {
        uint32_t guard = kNone;
        uint32_t uses = 0;
        Shape shape;
    };

    static bool isRuleReference(uint32_t value) { return (value & kRuleBit) && !(value & kGuardBit); }
    bool isGuard(uint32_t s) const { return symbols_[s].value & kGuardBit; }
    uint32_t value(uint32_t s) const { return symbols_[s].value; }
    uint32_t next(uint32_t s) const { return symbols_[s].next; }
    uint32_t prev(uint32_t s) const { return symbols_[s].prev; }
    uint32_t first(uint32_t rule) const { return symbols_[rules_[rule].guard].next; }
    uint32_t last(uint32_t rule) const { return symbols_[rules_[rule].guard].prev; }
    const Shape& shapeOf(uint32_t value) const {
        return isRuleReference(value) ? rules_[value & ~kRuleBit].shape : terminals_[value];
    }
    uint64_t digramOf(uint32_t s) const { return uint64_t{value(s)} << 32 | value(next(s)); }

    // Only digrams that may become rules are ever indexed (the legality rule).
    bool indexable(uint32_t s) const {
        return !isGuard(s) && !isGuard(next(s)) && mayBecomeRule(shapeOf(value(s)), shapeOf(value(next(s))));
    }

    // A slot of pool, reusing a freed one first.
    template <typename T>
    static uint32_t allocate(std::vector<T>& pool, std::vector<uint32_t>& freed) {
        if (freed.empty()) {
            pool.emplace_back();
            return static_cast<uint32_t>(pool.size() - 1);
        }
        const uint32_t slot = freed.back();
        freed.pop_back();
        return slot;
    }

    uint32_t newSymbol(uint32_t value) {
        if (isRuleReference(value)) ++rules_[value & ~kRuleBit].uses;
        const uint32_t s = allocate(symbols_, freeSymbols_);
        symbols_[s] = {value, kNone, kNone};
        return s;
    }

    uint32_t newRule(const Shape& shape) {
        const uint32_t rule = allocate(rules_, freeRules_);
        const uint32_t guard = newSymbol(kGuardBit | rule);
        symbols_[guard].prev = symbols_[guard].next = guard;
        rules_[rule] = {guard, 0, shape};
        return rule;
    }

    void forget(uint32_t s) {
        if (!indexable(s)) return;
        auto found = digrams_.find(digramOf(s));
        if (found != digrams_.end() && found->second == s) digrams_.erase(found);
    }

    void record(uint32_t s) {
        if (indexable(s)) digrams_[digramOf(s)] = s;
    }

    // Links left to right, forgetting left's old digram. In a run "aaa" only
    // the second pair is indexed; when it goes, the first one is recorded.
    void join(uint32_t left, uint32_t right) {
        if (next(left) != kNone) {
            forget(left);
            if (prev(right) != kNone && next(right) != kNone && value(right) == value(prev(right)) &&
                value(right) == value(next(right)))
                record(right);
            if (prev(left) != kNone && value(left) == value(next(left)) && value(left) == value(prev(left)))
                record(prev(left));
        }
        symbols_[left].next = right;
        symbols_[right].prev = left;
    }

    void insertAfter(uint32_t at, uint32_t s) {
        join(s, next(at));
        join(at, s);
    }

    void remove(uint32_t s) {
        join(prev(s), next(s));
        forget(s);
        if (isRuleReference(value(s))) --rules_[value(s) & ~kRuleBit].uses;
        freeSymbols_.push_back(s);
    }

    // Enforces digram uniqueness for the digram starting at s; returns whether it was already there.
    bool check(uint32_t s) {
        if (!indexable(s)) return false;
        auto [found, added] = digrams_.try_emplace(digramOf(s), s);
        if (added || found->second == s) return false;
        const uint32_t other = found->second;
        if (next(other) != s) match(s, other); // overlapping digrams ("aaa") are left alone
        return true;
    }

    // s and other start equal digrams: both become a reference to one rule.
    void match(uint32_t s, uint32_t other) {
        uint32_t rule;
        if (isGuard(prev(other)) && isGuard(next(next(other)))) { // other is a whole rule
            rule = value(prev(other)) & ~kGuardBit;
            substitute(s, rule);
        } else {
            rule = newRule(concatenate(shapeOf(value(s)), shapeOf(value(next(s)))));
            insertAfter(last(rule), newSymbol(value(s)));
            insertAfter(last(rule), newSymbol(value(next(s))));
            substitute(other, rule);
            substitute(s, rule);
            record(first(rule));
        }
        // Rule utility: a rule now used once inside the new one is inlined.
        const uint32_t head = first(rule);
        if (isRuleReference(value(head)) && rules_[value(head) & ~kRuleBit].uses == 1) inlineReference(head);
    }

    // Replaces the digram starting at s by a reference to rule.
    void substitute(uint32_t s, uint32_t rule) {
        const uint32_t before = prev(s);
        remove(next(before));
        remove(next(before));
        insertAfter(before, newSymbol(kRuleBit | rule));
        if (!check(before)) check(next(before));
    }

    // s is the last reference to its rule: the rule's body takes its place.
    void inlineReference(uint32_t s) {
        const uint32_t rule = value(s) & ~kRuleBit;
        const uint32_t left = prev(s), right = next(s);
        const uint32_t head = first(rule), tail = last(rule);
        forget(s);
        join(left, head);
        join(tail, right);
        record(tail);
        freeSymbols_.push_back(s);
        freeSymbols_.push_back(rules_[rule].guard);
        freeRules_.push_back(rule);
    }

    std::vector<Shape> terminals_; // per module index
    std::vector<Symbol> symbols_;
    std::vector<uint32_t> freeSymbols_;
    std::vector<Rule> rules_;
    std::vector<uint32_t> freeRules_;
    std::unordered_map<uint64_t, uint32_t> digrams_; // digram (two values) -> the symbol starting it
};

} // namespace

uint64_t compressionBytes(const ModuleString& word) {
    // Per module at worst (all distinct): its index (4 bytes), symbol (12),
    // digram entry (about 40 with its bucket), interned module with its hash
    // entry (about 32) and shape (12), and the rules finishBGrammar rewrites.
    constexpr uint64_t kBytesPerModule = 128;
    return bytesPlus(bytesTimes(word.size(), kBytesPerModule), bytesTimes(word.params.size(), sizeof(float)));
}

BGrammar compressWord(const ModuleString& word, size_t symbolCount, const BGrammarLimits& limits) {
    if (word.size() > limits.maxItems)
        throw DerivationError("b-grammar budget exceeded: the word to compress has " + std::to_string(word.size()) +
                              " modules, more than " + std::to_string(limits.maxItems) + " body items");
    BGrammar draft;
    draft.symbolCount = symbolCount;
    draft.method = BGrammarMethod::Compressed;
    ModuleInterner modules(draft);
    std::vector<uint32_t> terminals(word.size());
    for (size_t i = 0; i < word.size(); ++i) terminals[i] = modules.intern(word.symbols[i], word.parameters(i));
    if (draft.modules.size() >= kRuleBit) throw DerivationError("the word has more than 2^30 distinct modules");

    std::vector<Shape> shapes(draft.modules.size());
    for (size_t m = 0; m < draft.modules.size(); ++m) {
        if (draft.modules[m].symbol == kPush) shapes[m] = {1, 0, true};
        if (draft.modules[m].symbol == kPop) shapes[m] = {-1, -1, false};
    }
    Sequitur sequitur(std::move(shapes));
    for (uint32_t terminal : terminals) sequitur.append(terminal);
    sequitur.writeNodes(draft, limits);
    return finishBGrammar(std::move(draft), limits);
}

} // namespace lsys
