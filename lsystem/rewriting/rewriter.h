#pragma once
// Parallel rewriting of a ModuleString by a Grammar.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>

#include "lsystem/common/memory_budget.h"
#include "lsystem/language/grammar.h"
#include "lsystem/language/module_string.h"

namespace lsys {

struct DeriveOptions {
    std::optional<int> steps;       // default: the grammar's derivation length
    std::optional<uint64_t> seed;   // default: the grammar's seed
    size_t maxModules = 50'000'000; // a step producing more throws DerivationError
    // Each pass needs its input and its output string at once: more than
    // this throws MemoryBudgetError (stage "derivation") before the output is sized.
    MemoryBudget memory = machineMemoryBudget();
    int threads = 2;
    size_t parallelThreshold = 65'536; // strings shorter than this are rewritten on one thread
    // Called after each step with (step, steps, modules in the string): a
    // derivation may run for hours within its budgets (a large word rewritten
    // for a million steps), and tools show how far it is.
    std::function<void(int, int, size_t)> onStep;
};

// Where a module's random draws come from: derive() uses its seed, the pass
// number and the module's position in the string.
struct RandomSource {
    uint64_t seed = 0;
    uint64_t pass = 0;
    uint64_t position = 0;
};

// Rewrites one module by a context-free production set as one pass of
// derive() does: appends the successor, or the module itself when no
// production applies, to out, and says whether a production applied. With the
// source derive() would use at that pass and position the result is the one
// derive() writes there. Throws std::invalid_argument for a set with contexts.
bool rewriteModule(const ProductionSet& set, SymbolId symbol, std::span<const float> parameters,
                   const RandomSource& source, ModuleString& out);

// The cut symbol '%' when a rule or decomposition can produce it: derive()
// then removes cut branches after every step.
std::optional<SymbolId> producedCut(const Grammar& grammar);

// The axiom with its parameters evaluated (random draws use the given seed;
// global variables, of a grammar that has them, are read from `globals`).
ModuleString axiomString(const Grammar& grammar, uint64_t seed, const double* globals = nullptr);

// Axiom, then decomposition (unless Grammar::decomposeAxiom is false), then
// for each step: rules, decomposition, and the removal of branches cut by
// '%'. A sequential grammar (Grammar::sequential) is rewritten as cpfg
// rewrites: on one thread, left to right, with one
// random stream and its global variables, its Start: block run before the
// axiom is evaluated, StartEach: and EndEach: around each step and End:
// after the last.
// Throws DerivationError when the module budget is exceeded.
ModuleString derive(const Grammar& grammar, const DeriveOptions& options = {});

// Applies the interpretation (homomorphism) rules up to their maximum depth;
// used before the turtle reads the string. Returns the input when there are none.
ModuleString applyInterpretation(const Grammar& grammar, const ModuleString& string, const DeriveOptions& options = {});

} // namespace lsys
