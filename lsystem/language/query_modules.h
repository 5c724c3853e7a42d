#pragma once
// cpfg's query modules (Prusinkiewicz, James and Měch 1994, "Synthetic
// topiary", §2) as a grammar holds them: a '?' followed by P, H, L or U.
// finalizeGrammar marks a grammar that holds one (Grammar::queries); the
// turtle's answers are lsystem/rewriting/queries.h's.

#include <cstdint>
#include <vector>

#include "lsystem/language/grammar.h"

namespace lsys {

// Per symbol, the query it asks after a '?': 0 none, else 1 + the index of
// the vector it asks for (position, heading, left, up).
std::vector<uint8_t> queryKinds(const SymbolTable& symbols);

// Whether the axiom or any successor holds a query (a '?' followed by P, H, L or U).
bool hasQueries(const Grammar& grammar);

} // namespace lsys
