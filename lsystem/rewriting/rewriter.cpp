#include "lsystem/rewriting/rewriter.h"

#include <algorithm>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>

#include "lsystem/common/error.h"
#include "lsystem/common/random.h"
#include "lsystem/rewriting/context.h"
#include "lsystem/rewriting/queries.h"

namespace lsys {

namespace {

// Passes are numbered so every rewriting pass draws from its own random streams.
constexpr uint64_t kPassesPerStep = 1024;
constexpr uint64_t kAxiomPass = ~0ull;
constexpr uint64_t kInterpretationPass = 1ull << 62;

// A ProductionSet prepared for one derivation. Deterministic context-free
// rules without parameters (D0L) get a table of successor spans that are
// block-copied, and an exact output size computed before writing.
struct PreparedSet {
    const ProductionSet* set = nullptr;
    // Per symbol, the most modules and parameters one module can become (1 and
    // 0 without rules): a pass sizes its output from these before writing.
    std::vector<uint32_t> maxModules;
    std::vector<uint32_t> maxParameters;
    uint32_t longestSuccessor = 1;
    uint32_t mostArguments = 0; // of any successor module
    bool isD0L = false;
    std::vector<uint32_t> successorStart; // per symbol, into successorSymbols
    std::vector<uint32_t> successorLength;
    std::vector<SymbolId> successorSymbols;
};

PreparedSet prepare(const ProductionSet& set, size_t symbolCount) {
    PreparedSet prepared{&set};
    prepared.maxModules.assign(symbolCount, 1);
    prepared.maxParameters.assign(symbolCount, 0);
    for (const Production& production : set.productions) {
        uint32_t parameters = 0;
        for (const SuccessorModule& module : production.successor) {
            parameters += static_cast<uint32_t>(module.arguments.size());
            prepared.mostArguments = std::max(prepared.mostArguments, static_cast<uint32_t>(module.arguments.size()));
        }
        const SymbolId symbol = production.strict.symbol;
        prepared.maxModules[symbol] =
            std::max<uint32_t>(prepared.maxModules[symbol], static_cast<uint32_t>(production.successor.size()));
        prepared.maxParameters[symbol] = std::max(prepared.maxParameters[symbol], parameters);
        prepared.longestSuccessor = std::max(prepared.longestSuccessor, prepared.maxModules[symbol]);
    }
    prepared.isD0L = !set.contextSensitive && !set.producesParameters;
    for (const Production& production : set.productions)
        prepared.isD0L =
            prepared.isD0L && !production.condition && !production.stochastic && production.strict.paramCount == 0;
    if (!prepared.isD0L) return prepared;
    prepared.successorStart.resize(symbolCount);
    prepared.successorLength.assign(symbolCount, 1);
    for (size_t symbol = 0; symbol < symbolCount; ++symbol) {
        prepared.successorStart[symbol] = static_cast<uint32_t>(prepared.successorSymbols.size());
        if (set.bySymbol[symbol].empty()) {
            prepared.successorSymbols.push_back(static_cast<SymbolId>(symbol)); // no rule: copied
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

// Upper bounds of what a range of the input can become.
struct OutputBounds {
    size_t modules = 0;
    size_t parameters = 0;
    uint32_t mostParameters = 0; // of one input module
};

OutputBounds boundsOf(const PreparedSet& prepared, const ModuleString& in, Range range, bool withParameters) {
    OutputBounds bounds;
    for (size_t i = range.begin; i < range.end; ++i) {
        bounds.modules += prepared.maxModules[in.symbols[i]];
        if (!withParameters) continue;
        bounds.parameters += std::max(prepared.maxParameters[in.symbols[i]], in.paramCount(i));
        bounds.mostParameters = std::max(bounds.mostParameters, in.paramCount(i));
    }
    return bounds;
}

// Where a range writes its output: raw pointers into buffers sized from the
// bounds, so the loop has no reallocation and no capacity checks. Parameter
// offsets written to starts are absolute, counted from parameterBase.
struct Output {
    SymbolId* symbols;
    float* params;
    uint32_t* starts; // starts[k + 1] is written after the k-th module; null without parameters
    uint32_t parameterBase;
};

struct Written {
    size_t modules = 0;
    size_t parameters = 0;
    size_t rewritten = 0; // modules a production applied to
    bool withinBudget = true;
};

// The state a sequential grammar's derivation carries from module to module
// and step to step: its global variables, its one random stream and every
// production's local variables, which keep their values from one application
// to the next (cpfg: each production has its own symbol table, lsys_input.y).
struct SequentialState {
    std::vector<double> globals;
    RandomStream random;
    std::vector<double> locals; // Production::firstLocal indexes it
};

// The production that rewrites a module, or null when none applies. The
// module's parameters are bound to the formal variables; contexts are matched
// in view (which may be null for a context-free set). random is (re)started
// from source for every candidate that draws, as derive() always has, unless
// the grammar is sequential (state is set): then it is the derivation's one
// stream, and the candidate's statement blocks run around its condition
// (cpfg's order: the block before it once the predecessor matches, the one
// after it when it holds) with its kept local variables.
inline const Production* selectProduction(const ProductionSet& set, const ContextView* view, size_t position,
                                          SymbolId symbol, std::span<const float> parameters,
                                          const RandomSource& source, double* variables, RandomStream& random,
                                          SequentialState* state) {
    double* globals = state ? state->globals.data() : nullptr;
    const uint32_t inputCount = static_cast<uint32_t>(parameters.size());
    for (uint32_t index : set.bySymbol[symbol]) {
        const Production& production = set.productions[index];
        if (production.strict.paramCount != inputCount) continue;
        for (uint32_t k = 0; k < inputCount; ++k) variables[production.strict.firstVariable + k] = parameters[k];
        if (!production.strictTail.empty() && !matchStrictTail(*view, production.strictTail, position, variables))
            continue;
        if (!production.left.empty() && !matchLeft(*view, production.left, position, variables)) continue;
        if (!production.right.empty() &&
            !matchRight(*view, production.right, position + production.strictTail.size(), variables))
            continue;
        if (production.usesRandom && !state)
            random = RandomStream::forModule(source.seed, source.pass, source.position);
        double* kept = state ? state->locals.data() + production.firstLocal : nullptr;
        const size_t localCount = production.variables.size() - production.formalCount;
        auto runKeepingLocals = [&](const Block& block) {
            std::copy_n(kept, localCount, variables + production.formalCount);
            runBlock(block, variables, globals, random);
            std::copy_n(variables + production.formalCount, localCount, kept);
        };
        if (state) runKeepingLocals(production.before);
        if (production.condition && evaluate(*production.condition, variables, random, globals) == 0.0) continue;
        if (state) runKeepingLocals(production.after);
        const Production* chosen = &production;
        if (production.groupSize > 1) {
            // Pick an alternative by cumulative probability; the last absorbs rounding.
            double u = random.uniform();
            for (uint32_t k = 0; k + 1 < production.groupSize; ++k, ++chosen) {
                u -= chosen->probability;
                if (u < 0) break;
            }
        }
        return chosen;
    }
    return nullptr;
}

Written rewriteRange(const Grammar& grammar, const PreparedSet& prepared, const ModuleString& in,
                     const int32_t* partners, Range range, uint64_t seed, uint64_t pass, size_t budget, Output out,
                     SequentialState* sequential) {
    const ProductionSet& set = *prepared.set;
    const bool withParameters = out.starts != nullptr;
    SymbolId* symbols = out.symbols;
    float* params = out.params;
    uint32_t* starts = out.starts;
    size_t written = 0;
    uint32_t parameterEnd = out.parameterBase;
    size_t applied = 0;

    const ContextView view{in, partners, grammar.ignored.data(), grammar.ring, grammar.cpfgContexts};
    double variables[kMaxVariables];
    double* globals = sequential ? sequential->globals.data() : nullptr;
    RandomStream ownStream;
    RandomStream& random = sequential ? sequential->random : ownStream;
    for (size_t i = range.begin; i < range.end; ++i) {
        const SymbolId symbol = in.symbols[i];
        const uint32_t inputCount = in.paramCount(i);
        const float* inputParameters = in.paramData(i);
        const Production* chosen = selectProduction(set, &view, i, symbol, {inputParameters, inputCount},
                                                    {seed, pass, i}, variables, random, sequential);
        if (!chosen) { // no production applies: copy the module
            symbols[written++] = symbol;
            if (withParameters) {
                std::copy(inputParameters, inputParameters + inputCount, params);
                params += inputCount;
                parameterEnd += inputCount;
                starts[written] = parameterEnd;
            }
        } else {
            ++applied;
            i += chosen->strictTail.size(); // the predecessor's other modules are replaced too
            for (const SuccessorModule& module : chosen->successor) {
                symbols[written++] = module.symbol;
                if (!withParameters) continue;
                for (const Expression& argument : module.arguments)
                    *params++ = static_cast<float>(evaluate(argument, variables, random, globals));
                parameterEnd += static_cast<uint32_t>(module.arguments.size());
                starts[written] = parameterEnd;
            }
        }
        // The output was sized for at most budget + one successor: stop before passing it.
        if (written > budget) return {written, parameterEnd - out.parameterBase, applied, false};
    }
    return {written, parameterEnd - out.parameterBase, applied, true};
}

[[noreturn]] void budgetExceeded(size_t budget, uint64_t pass) {
    std::string when = pass >= kInterpretationPass ? "while applying interpretation rules"
                                                   : "at derivation step " + std::to_string(pass / kPassesPerStep);
    throw ModuleBudgetError("module budget exceeded " + when + ": the string would have more than " +
                            std::to_string(budget) + " modules");
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
    SequentialState* sequential = nullptr; // set for sequential grammars: one range, in string order
    std::vector<int32_t> partners;

    std::vector<Range> split(size_t n, bool oneRange = false) const {
        size_t count = (options.threads > 1 && n >= options.parallelThreshold && !sequential && !oneRange)
                           ? static_cast<size_t>(options.threads)
                           : 1;
        std::vector<Range> ranges;
        for (size_t t = 0; t < count; ++t) ranges.push_back({n * t / count, n * (t + 1) / count});
        return ranges;
    }

    // One pass of set over in, into out. Returns how many modules were rewritten by a production.
    // Each range writes straight into out at the offset its bounds allow;
    // the gaps left where a range wrote less than its bound are closed after.
    size_t pass(const PreparedSet& prepared, uint64_t passNumber, const ModuleString& in, ModuleString& out) {
        if (prepared.isD0L && !in.hasParameters()) return passD0L(prepared, passNumber, in, out);
        if (prepared.set->contextSensitive) computeBracketPartners(in, partners);
        const bool withParameters = in.hasParameters() || prepared.set->producesParameters;
        const std::vector<Range> ranges = split(in.size(), prepared.set->consumesSeveral);
        const size_t count = ranges.size();
        const size_t moduleCap = options.maxModules + prepared.longestSuccessor;

        std::vector<OutputBounds> bounds(count);
        runParallel(count, [&](size_t t) { bounds[t] = boundsOf(prepared, in, ranges[t], withParameters); });
        std::vector<size_t> moduleOffset(count + 1, 0), parameterOffset(count + 1, 0);
        for (size_t t = 0; t < count; ++t) {
            const size_t modules = std::min(bounds[t].modules, moduleCap);
            // Near the budget the sum of the per-module bounds can be far more than the
            // capped modules can hold: bound the parameters by what those modules can carry.
            const size_t perModule = std::max(prepared.mostArguments, bounds[t].mostParameters);
            moduleOffset[t + 1] = moduleOffset[t] + modules;
            parameterOffset[t + 1] = parameterOffset[t] + std::min(bounds[t].parameters, modules * perModule);
        }
        if (parameterOffset.back() > UINT32_MAX) throw DerivationError("too many parameters in one string (over 4 G)");
        need(options.memory, "derivation",
             bytesPlus(moduleStringBytes(in),
                       moduleStringBytes(moduleOffset.back(), parameterOffset.back(), withParameters)));
        out.symbols.resize(moduleOffset.back());
        out.params.resize(parameterOffset.back());
        out.paramStart.resize(withParameters ? moduleOffset.back() + 1 : 0);
        if (withParameters) out.paramStart[0] = 0;

        std::vector<Written> written(count);
        runParallel(count, [&](size_t t) {
            Output target{out.symbols.data() + moduleOffset[t], out.params.data() + parameterOffset[t],
                          withParameters ? out.paramStart.data() + moduleOffset[t] : nullptr,
                          static_cast<uint32_t>(parameterOffset[t])};
            written[t] = rewriteRange(grammar, prepared, in, partners.data(), ranges[t], seed, passNumber,
                                      options.maxModules, target, sequential);
        });

        size_t modules = 0, parameters = 0, rewritten = 0;
        for (size_t t = 0; t < count; ++t) {
            if (!written[t].withinBudget) budgetExceeded(options.maxModules, passNumber);
            closeGap(out, withParameters, moduleOffset[t], parameterOffset[t], modules, parameters, written[t]);
            modules += written[t].modules;
            parameters += written[t].parameters;
            rewritten += written[t].rewritten;
        }
        if (modules > options.maxModules) budgetExceeded(options.maxModules, passNumber);
        out.symbols.resize(modules);
        out.params.resize(parameters);
        if (withParameters) out.paramStart.resize(modules + 1);
        return rewritten;
    }

    // Moves a range's output from where it was written down to where it belongs.
    static void closeGap(ModuleString& out, bool withParameters, size_t fromModule, size_t fromParameter,
                         size_t toModule, size_t toParameter, const Written& written) {
        if (fromModule == toModule && fromParameter == toParameter) return;
        // Destinations lie before sources, so a forward copy is safe although the ranges overlap.
        std::copy_n(out.symbols.data() + fromModule, written.modules, out.symbols.data() + toModule);
        if (!withParameters) return;
        std::copy_n(out.params.data() + fromParameter, written.parameters, out.params.data() + toParameter);
        const uint32_t shift = static_cast<uint32_t>(fromParameter - toParameter);
        uint32_t* starts = out.paramStart.data();
        for (size_t k = 1; k <= written.modules; ++k) starts[toModule + k] = starts[fromModule + k] - shift;
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
        need(options.memory, "derivation",
             bytesPlus(moduleStringBytes(in), moduleStringBytes(outputStart.back(), 0, false)));
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
                    write = std::copy_n(successors + start[symbol], count, write);
                }
            }
        });
        size_t total = 0;
        for (size_t count : applied) total += count;
        return total;
    }

    // Applies set repeatedly (at most maxDepth passes) until no rule applies.
    void passesToFixpoint(const PreparedSet& prepared, uint64_t firstPass, ModuleString& string,
                          ModuleString& scratch) {
        for (int depth = 0; depth < prepared.set->maxDepth; ++depth) {
            size_t applied = pass(prepared, firstPass + static_cast<uint64_t>(depth), string, scratch);
            std::swap(string, scratch);
            if (applied == 0) break;
        }
    }
};

// lpfg's cut: a '%' and everything after it up to the end of its branch
// disappear from the string (the closing ']' stays).
void removeCutBranches(const ModuleString& in, SymbolId cut, ModuleString& out) {
    out.clear();
    if (in.hasParameters()) out.addOffsets();
    for (size_t i = 0; i < in.size(); ++i) {
        if (in.symbols[i] != cut) {
            out.push(in.symbols[i], in.parameters(i));
            continue;
        }
        int depth = 0;
        while (i + 1 < in.size() && !(in.symbols[i + 1] == kPop && depth == 0)) {
            depth += in.symbols[i + 1] == kPush ? 1 : in.symbols[i + 1] == kPop ? -1 : 0;
            ++i;
        }
    }
}

} // namespace

std::optional<SymbolId> producedCut(const Grammar& grammar) {
    std::optional<SymbolId> cut = grammar.symbols.find("%");
    if (!cut) return std::nullopt;
    for (const ProductionSet* set : {&grammar.rules, &grammar.decomposition})
        for (const Production& production : set->productions)
            for (const SuccessorModule& module : production.successor)
                if (module.symbol == *cut) return cut;
    return std::nullopt;
}

bool rewriteModule(const ProductionSet& set, SymbolId symbol, std::span<const float> parameters,
                   const RandomSource& source, ModuleString& out) {
    if (set.contextSensitive)
        throw std::invalid_argument("rewriteModule: the production set has context-sensitive productions");
    double variables[kMaxVariables];
    RandomStream random;
    const Production* chosen =
        selectProduction(set, nullptr, 0, symbol, parameters, source, variables, random, nullptr);
    if (!chosen) {
        out.push(symbol, parameters);
        return false;
    }
    std::vector<float> values;
    for (const SuccessorModule& module : chosen->successor) {
        values.clear();
        for (const Expression& argument : module.arguments)
            values.push_back(static_cast<float>(evaluate(argument, variables, random)));
        out.push(module.symbol, values);
    }
    return true;
}

ModuleString axiomString(const Grammar& grammar, uint64_t seed, const double* globals) {
    ModuleString string;
    std::vector<float> values;
    for (size_t i = 0; i < grammar.axiom.size(); ++i) {
        const SuccessorModule& module = grammar.axiom[i];
        RandomStream random = RandomStream::forModule(seed, kAxiomPass, i);
        values.clear();
        for (const Expression& argument : module.arguments)
            values.push_back(static_cast<float>(evaluate(argument, nullptr, random, globals)));
        string.push(module.symbol, values);
    }
    return string;
}

namespace {

// Running out of memory below the module budget is reported like the budget itself.
template <typename Work>
ModuleString withinMemory(Work work) {
    try {
        return work();
    } catch (const std::bad_alloc&) {
        throw ModuleBudgetError("out of memory while deriving, below the module budget");
    }
}

// A sequential grammar's state as its Start: block leaves it (cpfg runs it
// before the axiom is evaluated); empty for other grammars.
std::optional<SequentialState> startState(const Grammar& grammar, uint64_t seed) {
    if (!grammar.sequential) return std::nullopt;
    SequentialState state{grammar.globals.initial, RandomStream::forModule(seed, kAxiomPass, ~0ull),
                          std::vector<double>(grammar.localCount, 0.0)};
    runBlock(grammar.startBlock, nullptr, state.globals.data(), state.random);
    return state;
}

// Runs one of a sequential grammar's global blocks; nothing for other grammars.
void runGlobalBlock(const Block& block, std::optional<SequentialState>& state) {
    if (state) runBlock(block, nullptr, state->globals.data(), state->random);
}

ModuleString deriveUnguarded(const Grammar& grammar, const DeriveOptions& options) {
    const uint64_t seed = options.seed.value_or(grammar.seed);
    const int steps = options.steps.value_or(grammar.derivationLength);
    std::optional<SequentialState> state = startState(grammar, seed);
    Rewriter rewriter{grammar, options, seed, state ? &*state : nullptr};
    const size_t symbolCount = grammar.symbols.size();
    const PreparedSet rules = prepare(grammar.rules, symbolCount);
    const PreparedSet decomposition = prepare(grammar.decomposition, symbolCount);

    const std::optional<SymbolId> cut = producedCut(grammar);
    ModuleString current = axiomString(grammar, seed, state ? state->globals.data() : nullptr);
    if (current.size() > options.maxModules) budgetExceeded(options.maxModules, 0);
    ModuleString next;
    if (!grammar.decomposition.empty() && grammar.decomposeAxiom)
        rewriter.passesToFixpoint(decomposition, 1, current, next);
    for (int step = 1; step <= steps; ++step) {
        const uint64_t passNumber = static_cast<uint64_t>(step) * kPassesPerStep;
        runGlobalBlock(grammar.startEachBlock, state);
        if (cut && grammar.cutInNextStep) {
            removeCutBranches(current, *cut, next);
            std::swap(current, next);
        }
        if (grammar.queries) answerQueries(grammar, current); // the turtle's answers from the string as it stands
        if (!grammar.rules.empty()) {
            rewriter.pass(rules, passNumber, current, next);
            std::swap(current, next);
        }
        if (!grammar.decomposition.empty()) rewriter.passesToFixpoint(decomposition, passNumber + 1, current, next);
        if (cut && !grammar.cutInNextStep) {
            removeCutBranches(current, *cut, next);
            std::swap(current, next);
        }
        runGlobalBlock(grammar.endEachBlock, state);
        if (options.onStep) options.onStep(step, steps, current.size());
    }
    runGlobalBlock(grammar.endBlock, state);
    if (grammar.queries) answerQueries(grammar, current); // as cpfg's drawing of the string answers them
    return current;
}

ModuleString interpretUnguarded(const Grammar& grammar, const ModuleString& string, const DeriveOptions& options) {
    ModuleString current = string;
    if (grammar.interpretation.empty()) return current;
    const uint64_t seed = options.seed.value_or(grammar.seed);
    // Interpretation rules read the global variables as the Start: block leaves them.
    std::optional<SequentialState> state = startState(grammar, seed);
    Rewriter rewriter{grammar, options, seed, state ? &*state : nullptr};
    const PreparedSet interpretation = prepare(grammar.interpretation, grammar.symbols.size());
    ModuleString scratch;
    rewriter.passesToFixpoint(interpretation, kInterpretationPass, current, scratch);
    return current;
}

} // namespace

ModuleString derive(const Grammar& grammar, const DeriveOptions& options) {
    return withinMemory([&] { return deriveUnguarded(grammar, options); });
}

ModuleString applyInterpretation(const Grammar& grammar, const ModuleString& string, const DeriveOptions& options) {
    return withinMemory([&] { return interpretUnguarded(grammar, string, options); });
}

} // namespace lsys
