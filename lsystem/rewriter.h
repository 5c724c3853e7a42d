#pragma once
// Parallel rewriting of a ModuleString by a Grammar.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "lsystem/grammar.h"
#include "lsystem/module_string.h"

namespace lsys {

struct DeriveOptions {
    std::optional<int> steps;       // default: the grammar's derivation length
    std::optional<uint64_t> seed;   // default: the grammar's seed
    size_t maxModules = 50'000'000; // a step producing more throws DerivationError
    int threads = 2;
    size_t parallelThreshold = 65'536;  // strings shorter than this are rewritten on one thread
};

// The axiom with its parameters evaluated (random draws use the given seed).
ModuleString axiomString(const Grammar& grammar, uint64_t seed);

// Axiom, then decomposition, then for each step: rules, decomposition, and
// the removal of branches cut by '%'.
// Throws DerivationError when the module budget is exceeded.
ModuleString derive(const Grammar& grammar, const DeriveOptions& options = {});

// Applies the interpretation (homomorphism) rules up to their maximum depth;
// used before the turtle reads the string. Returns the input when there are none.
ModuleString applyInterpretation(const Grammar& grammar, const ModuleString& string, const DeriveOptions& options = {});

}  // namespace lsys
