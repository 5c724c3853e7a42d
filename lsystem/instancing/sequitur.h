#pragma once
// Grammar-based compression of a derived word into a b-grammar (Calgary
// b-grammar thesis, ch. 6), for the L-systems whose rewriting cannot be shared
// by key: context-sensitive or cut rules, random draws without a randomness
// factor.
//
// SEQUITUR (Nevill-Manning & Witten 1997) reads the word module by module
// (equal symbol and parameter bits are the same terminal) and keeps two
// constraints, each restored in amortised constant time per module: no digram
// (pair of adjacent symbols) occurs twice in the grammar, and every rule is
// used at least twice.
//
// Bracket legality (the thesis, §6.2) takes precedence: a digram that would make
// an illegal or unhelpful rule is never indexed, so it may repeat. A digram xy
// (x, y terminals or rules standing for their expansions) becomes a rule only
// when
//   - its expansion never pops below its start: lowest(x) >= 0 and
//     depth(x) + lowest(y) >= 0 (no leading ']', no ']' right after a
//     balanced x), so every rule has a turtle status function; and
//   - if it leaves states pushed (depth(x) + depth(y) > 0), its expansion
//     starts with '[': rules then gather whole branches "[...]" instead of
//     partial axes like "F[+F", the grouping the thesis found more compact.
// Inlining a rule used once never changes an expansion, so rules stay legal.

#include "lsystem/instancing/bgrammar.h"

namespace lsys {

// What compressWord holds besides the word: per module a terminal index, a
// symbol of the grammar and an entry of the digram index, and the draft's
// modules and parameters.
uint64_t compressionBytes(const ModuleString& word);

// A b-grammar generating exactly word (method Compressed); symbolCount is the
// size of the grammar's symbol table. Throws DerivationError past the limits
// (a word longer than limits.maxItems is refused before compressing).
BGrammar compressWord(const ModuleString& word, size_t symbolCount, const BGrammarLimits& limits = {});

} // namespace lsys
