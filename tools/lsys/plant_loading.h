// The plant file a deriving command starts from: FILE, -n, --seed, -D,
// --dialect and --memory-budget on the command line, the file or vlab object
// read in its dialect with -D's constants (its problems printed), how it is
// derived, the b-grammar of the word the turtle reads, and what a failure to
// derive prints.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lsystem/common/memory_budget.h"
#include "lsystem/dialects/dialect.h"
#include "lsystem/instancing/bgrammar.h"
#include "lsystem/language/grammar.h"
#include "lsystem/rewriting/rewriter.h"

namespace tools {

// lsys' exit status for bad input: a file's problems, a budget exceeded.
inline constexpr int kBadInput = 2;

// What every command that derives a plant file reads from its command line.
struct DerivationArguments {
    std::string file;
    std::optional<int> steps;
    std::optional<uint64_t> seed;
    std::vector<std::string> defines;     // -D's "NAME=VALUE" items
    std::optional<lsys::Dialect> dialect; // none: the file's "dialect:" line, else cpfg for a .l file, else native
    size_t maxModules = 50'000'000;       // --max-modules, which each command words for itself
    lsys::MemoryBudget memory;            // --memory-budget
};

// FILE, -D and --dialect: what reading the file takes (lsys check).
void addPlantFileOptions(CLI::App& command, DerivationArguments& arguments);

// The file's options, -n, --seed and --memory-budget: what deriving it takes.
void addDerivationOptions(CLI::App& command, DerivationArguments& arguments);

// Parses the file (lsystem/vlab/object.h: a file or a vlab object folder)
// with -D's constants overriding its #define constants. Prints warnings to
// stderr; on problems prints them all and returns nullopt.
std::optional<lsys::Grammar> loadGrammar(const DerivationArguments& arguments);

// Prints what went wrong with the file, and the way out of a budget; kBadInput.
int failed(const DerivationArguments& arguments, const std::exception& error);

// Prints how far a long derivation is to stderr, every 5 s once it has run
// 5 s ("lsys: step 120 of 1000000, 524288 modules, about 2 h 10 min left"),
// so that a derivation of hours is seen to be one (Ctrl+C stops it).
std::function<void(int, int, size_t)> derivationProgress();

// -n, --seed, --max-modules and --memory-budget, as derive() takes them, and
// derivationProgress.
lsys::DeriveOptions deriveOptions(const DerivationArguments& arguments);

// The options of the b-grammar of the word the turtle reads, as lsys
// instance, export --instanced and render build it, and derivationProgress.
lsys::BGrammarOptions bgrammarOptions(const DerivationArguments& arguments);

} // namespace tools
