#pragma once
// What the parser does with a section's productions once the whole file is
// read: it groups stochastic alternatives and warns of successors whose
// brackets do not balance.

#include <span>
#include <string>
#include <vector>

#include "lsystem/error.h"
#include "lsystem/grammar.h"

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

} // namespace lsys
