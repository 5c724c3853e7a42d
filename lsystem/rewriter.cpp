#include "lsystem/rewriter.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <string>
#include <thread>

#include "lsystem/context.h"
#include "lsystem/error.h"
#include "lsystem/random.h"

namespace lsys {

namespace {

// Passes are numbered so every rewriting pass draws from its own random streams.
constexpr uint64_t kPassesPerStep = 1024;
constexpr uint64_t kAxiomPass = ~0ull;
constexpr uint64_t kInterpretationPass = 1ull << 62;

// A ProductionSet prepared for one derivation. Deterministic context-free
// rules without parameters (D0L) get a table of successor spans copied with
// memcpy, and an exact output size computed before writing.
struct PreparedSet {
    const ProductionSet* set = nullptr;
    bool isD0L = false;
    std::vector<uint32_t> successorStart;  // per symbol, into successorSymbols
    std::vector<uint32_t> successorLength;
    std::vector<SymbolId> successorSymbols;
};

PreparedSet prepare(const ProductionSet& set, size_t symbolCount) {
    PreparedSet prepared{&set};
    prepared.isD0L = !set.contextSensitive && !set.producesParameters;
    for (const Production& production : set.productions)
        prepared.isD0L = prepared.isD0L && !production.condition && !production.stochastic && production.strict.paramCount == 0;
    if (!prepared.isD0L) return prepared;
    prepared.successorStart.resize(symbolCount);
    prepared.successorLength.assign(symbolCount, 1);
    for (size_t symbol = 0; symbol < symbolCount; ++symbol) {
        prepared.successorStart[symbol] = static_cast<uint32_t>(prepared.successorSymbols.size());
        if (set.bySymbol[symbol].empty()) {
            prepared.successorSymbols.push_back(static_cast<SymbolId>(symbol));  // no rule: copied
            continue;
        }
        const Production& production = set.productions[set.bySymbol[symbol].front()];
        prepared.successorLength[symbol] = static_cast<uint32_t>(production.successor.size());
        for (const SuccessorModule& module : production.successor) prepared.successorSymbols.push_back(module.symbol);
    }
    return prepared;
}

struct Range {
    size_t begin, end;
};

// Rewrites in[range] into out (cleared first). Returns false when out grows past budget.
bool rewriteRange(const Grammar& grammar, const PreparedSet& prepared, const ModuleString& in, const int32_t* partners,
                  Range range, uint64_t seed, uint64_t pass, size_t budget, ModuleString& out, size_t& applied) {
    const ProductionSet& set = *prepared.set;
    const bool withParameters = in.hasParameters() || set.producesParameters;
    out.clear();
    if (withParameters) out.paramStart.push_back(0);
    const ContextView view{in, partners, grammar.ignored.data()};
    double variables[kMaxVariables];

    auto copyModule = [&](size_t i) {
        out.symbols.push_back(in.symbols[i]);
        if (withParameters) {
            const uint32_t count = in.paramCount(i);
            if (count) out.params.insert(out.params.end(), in.paramData(i), in.paramData(i) + count);
            out.paramStart.push_back(static_cast<uint32_t>(out.params.size()));
        }
    };

    for (size_t i = range.begin; i < range.end; ++i) {
        const std::vector<uint32_t>& candidates = set.bySymbol[in.symbols[i]];
        const Production* chosen = nullptr;
        RandomStream random;
        if (!candidates.empty()) {
            const uint32_t paramCount = in.paramCount(i);
            const float* parameters = in.paramData(i);
            for (uint32_t index : candidates) {
                const Production& production = set.productions[index];
                if (production.strict.paramCount != paramCount) continue;
                for (uint32_t k = 0; k < paramCount; ++k) variables[production.strict.firstVariable + k] = parameters[k];
                if (!production.left.empty() && !matchLeft(view, production.left, i, variables)) continue;
                if (!production.right.empty() && !matchRight(view, production.right, i, variables)) continue;
                if (production.usesRandom) random = RandomStream::forModule(seed, pass, i);
                if (production.condition && evaluate(*production.condition, variables, random) == 0.0) continue;
                chosen = &production;
                if (production.groupSize > 1) {
                    // Pick an alternative by cumulative probability; the last absorbs rounding.
                    double u = random.uniform();
                    for (uint32_t k = 0; k + 1 < production.groupSize; ++k, ++chosen) {
                        u -= chosen->probability;
                        if (u < 0) break;
                    }
                }
                break;
            }
        }
        if (!chosen) {
            copyModule(i);
            continue;
        }
        ++applied;
        for (const SuccessorModule& module : chosen->successor) {
            out.symbols.push_back(module.symbol);
            if (!withParameters) continue;
            for (const Expression& argument : module.arguments)
                out.params.push_back(static_cast<float>(evaluate(argument, variables, random)));
            out.paramStart.push_back(static_cast<uint32_t>(out.params.size()));
        }
        if (out.symbols.size() > budget) return false;
    }
    return true;
}

[[noreturn]] void budgetExceeded(size_t budget, uint64_t pass) {
    std::string when = pass >= kInterpretationPass ? "while applying interpretation rules"
                                                   : "at derivation step " + std::to_string(pass / kPassesPerStep);
    throw DerivationError("module budget exceeded " + when + ": the string would have more than " +
                          std::to_string(budget) + " modules (raise it with --max-modules)");
}

// Runs one function per range, the first on the calling thread.
template <typename Work>
void runParallel(size_t count, Work work) {
    std::vector<std::thread> threads;
    std::vector<std::exception_ptr> errors(count);
    for (size_t t = 1; t < count; ++t)
        threads.emplace_back([&, t] {
            try {
                work(t);
            } catch (...) {
                errors[t] = std::current_exception();
            }
        });
    try {
        work(0);
    } catch (...) {
        errors[0] = std::current_exception();
    }
    for (std::thread& thread : threads) thread.join();
    for (std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
}

struct Rewriter {
    const Grammar& grammar;
    const DeriveOptions& options;
    uint64_t seed;
    std::vector<int32_t> partners;
    std::vector<ModuleString> chunks;  // per extra thread, reused across passes

    std::vector<Range> split(size_t n) const {
        size_t count = (options.threads > 1 && n >= options.parallelThreshold) ? static_cast<size_t>(options.threads) : 1;
        std::vector<Range> ranges;
        for (size_t t = 0; t < count; ++t) ranges.push_back({n * t / count, n * (t + 1) / count});
        return ranges;
    }

    // One pass of set over in, into out. Returns how many modules were rewritten by a production.
    size_t pass(const PreparedSet& prepared, uint64_t passNumber, const ModuleString& in, ModuleString& out) {
        if (prepared.isD0L && !in.hasParameters()) return passD0L(prepared, passNumber, in, out);
        if (prepared.set->contextSensitive) computeBracketPartners(in, partners);
        std::vector<Range> ranges = split(in.size());
        if (chunks.size() < ranges.size()) chunks.resize(ranges.size());
        std::vector<size_t> applied(ranges.size(), 0);
        std::vector<char> withinBudget(ranges.size(), 1);
        runParallel(ranges.size(), [&](size_t t) {
            ModuleString& target = t == 0 ? out : chunks[t];
            withinBudget[t] = rewriteRange(grammar, prepared, in, partners.data(), ranges[t], seed, passNumber,
                                           options.maxModules, target, applied[t]);
        });
        size_t total = 0;
        for (size_t t = 0; t < ranges.size(); ++t) {
            if (!withinBudget[t]) budgetExceeded(options.maxModules, passNumber);
            total += t == 0 ? out.size() : chunks[t].size();
            applied[0] += t == 0 ? 0 : applied[t];
        }
        if (total > options.maxModules) budgetExceeded(options.maxModules, passNumber);
        for (size_t t = 1; t < ranges.size(); ++t) out.append(chunks[t]);
        return applied[0];
    }

    size_t passD0L(const PreparedSet& prepared, uint64_t passNumber, const ModuleString& in, ModuleString& out) {
        std::vector<Range> ranges = split(in.size());
        std::vector<size_t> outputStart(ranges.size() + 1, 0);
        std::vector<size_t> applied(ranges.size(), 0);
        const SymbolId* symbols = in.symbols.data();
        const uint32_t* length = prepared.successorLength.data();
        runParallel(ranges.size(), [&](size_t t) {
            size_t size = 0, rewritten = 0;
            for (size_t i = ranges[t].begin; i < ranges[t].end; ++i) {
                size += length[symbols[i]];
                rewritten += !prepared.set->bySymbol[symbols[i]].empty();
            }
            outputStart[t + 1] = size;
            applied[t] = rewritten;
        });
        for (size_t t = 0; t < ranges.size(); ++t) outputStart[t + 1] += outputStart[t];
        if (outputStart.back() > options.maxModules) budgetExceeded(options.maxModules, passNumber);
        out.clear();
        out.symbols.resize(outputStart.back());
        const uint32_t* start = prepared.successorStart.data();
        const SymbolId* successors = prepared.successorSymbols.data();
        runParallel(ranges.size(), [&](size_t t) {
            SymbolId* write = out.symbols.data() + outputStart[t];
            for (size_t i = ranges[t].begin; i < ranges[t].end; ++i) {
                const SymbolId symbol = symbols[i];
                const uint32_t count = length[symbol];
                if (count == 1) {
                    *write++ = successors[start[symbol]];
                } else {
                    std::memcpy(write, successors + start[symbol], count * sizeof(SymbolId));
                    write += count;
                }
            }
        });
        size_t total = 0;
        for (size_t count : applied) total += count;
        return total;
    }

    // Applies set repeatedly (at most maxDepth passes) until no rule applies.
    void passesToFixpoint(const PreparedSet& prepared, uint64_t firstPass, ModuleString& string, ModuleString& scratch) {
        for (int depth = 0; depth < prepared.set->maxDepth; ++depth) {
            size_t applied = pass(prepared, firstPass + static_cast<uint64_t>(depth), string, scratch);
            std::swap(string, scratch);
            if (applied == 0) break;
        }
    }
};

}  // namespace

ModuleString axiomString(const Grammar& grammar, uint64_t seed) {
    ModuleString string;
    std::vector<float> values;
    for (size_t i = 0; i < grammar.axiom.size(); ++i) {
        const SuccessorModule& module = grammar.axiom[i];
        RandomStream random = RandomStream::forModule(seed, kAxiomPass, i);
        values.clear();
        for (const Expression& argument : module.arguments)
            values.push_back(static_cast<float>(evaluate(argument, nullptr, random)));
        string.push(module.symbol, values);
    }
    return string;
}

ModuleString derive(const Grammar& grammar, const DeriveOptions& options) {
    const uint64_t seed = options.seed.value_or(grammar.seed);
    const int steps = options.steps.value_or(grammar.derivationLength);
    Rewriter rewriter{grammar, options, seed};
    const size_t symbolCount = grammar.symbols.size();
    const PreparedSet rules = prepare(grammar.rules, symbolCount);
    const PreparedSet decomposition = prepare(grammar.decomposition, symbolCount);

    ModuleString current = axiomString(grammar, seed);
    if (current.size() > options.maxModules) budgetExceeded(options.maxModules, 0);
    ModuleString next;
    if (!grammar.decomposition.empty()) rewriter.passesToFixpoint(decomposition, 1, current, next);
    for (int step = 1; step <= steps; ++step) {
        const uint64_t passNumber = static_cast<uint64_t>(step) * kPassesPerStep;
        if (!grammar.rules.empty()) {
            rewriter.pass(rules, passNumber, current, next);
            std::swap(current, next);
        }
        if (!grammar.decomposition.empty()) rewriter.passesToFixpoint(decomposition, passNumber + 1, current, next);
    }
    return current;
}

ModuleString applyInterpretation(const Grammar& grammar, const ModuleString& string, const DeriveOptions& options) {
    ModuleString current = string;
    if (grammar.interpretation.empty()) return current;
    Rewriter rewriter{grammar, options, options.seed.value_or(grammar.seed)};
    const PreparedSet interpretation = prepare(grammar.interpretation, grammar.symbols.size());
    ModuleString scratch;
    rewriter.passesToFixpoint(interpretation, kInterpretationPass, current, scratch);
    return current;
}

}  // namespace lsys
