#pragma once
// What the parser does with a section's productions once the whole file is
// read: it groups stochastic alternatives and warns of successors whose
// brackets do not balance and of cpfg productions that would rewrite more in
// cpfg than here.

#include <span>
#include <string>
#include <vector>

#include "lsystem/common/error.h"
#include "lsystem/language/grammar.h"

namespace lsys {

// Consecutive stochastic productions with the same predecessor (contexts
// and condition included; signatures[i] is production i's, spaces left out)
// form a group whose probabilities sum to 1: sets groupSize, and reports a
// group whose sum is not 1 in `diagnostics`.
void formStochasticGroups(ProductionSet& set, std::span<const std::string> signatures, const std::string& file,
                          std::vector<Diagnostic>& diagnostics);

// A warning for each successor whose brackets do not balance (less those of
// the strict predecessor it replaces, cpfg's "B [ --> C ["): it leaves a
// branch open or closes one it did not open, legal but seldom meant.
void warnOfUnbalancedBrackets(const ProductionSet& set, const std::string& file, std::vector<Diagnostic>& warnings);

// cpfg's lexer reads every module name as one character (lsys_input.l), so
// its `@o(1)` is the two modules `@` and `o(1)`, joined only by its turtle
// (interpret.c, call_blackbox): a production of `o` rewrites the `o` of
// `@o(1)` too. Here `@o` is one module, which only its own productions
// rewrite. A warning, in files read with cpfg's turtle modules, for each
// production of a module X when `@X` occurs in the file.
void warnOfCpfgAtModules(const Grammar& grammar, const ProductionSet& set, const std::string& file,
                         std::vector<Diagnostic>& warnings);

// cpfg's sub-L-systems (Prusinkiewicz, Hanan and Měch 1999, §2): `?(n, s)`
// in a successor starts a part of the string that L-system n rewrites, its
// turtle scaled by s, up to the matching `$`. They are not read here: the
// `?(n, s)` is an ordinary module and the `$` no command (cpfg's turtle
// skips a `$` that ends nothing). A warning, in files read with cpfg's
// turtle modules, for each production whose successor starts one.
void warnOfCpfgSubLsystems(const Grammar& grammar, const ProductionSet& set, const std::string& file,
                           std::vector<Diagnostic>& warnings);

} // namespace lsys
