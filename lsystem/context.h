#pragma once
// Context matching with lpfg's bracket rules.
//
// Left context: walks leftwards from the module, skipping ignored symbols,
// skipping whole bracketed branches "[...]" that lie before it on the same
// axis, and climbing from a branch to its parent axis at '['.
//
// Right context: walks rightwards, skipping ignored symbols and whole lateral
// branches that the pattern does not mention; a ']' in the string ends the
// search (the branch is over). A '[' in the pattern descends into a lateral
// branch (trying each branch at that node in turn); a ']' in the pattern skips
// the rest of the branch it is in.

#include <cstdint>
#include <span>

#include "lsystem/grammar.h"
#include "lsystem/module_string.h"

namespace lsys {

struct ContextView {
    const ModuleString& string;
    const int32_t* partners; // computeBracketPartners of string
    const uint8_t* ignored;  // per symbol
};

// On success the parameters of the context modules are written to variables
// at each pattern module's firstVariable.
bool matchLeft(const ContextView& view, std::span<const PatternModule> pattern, size_t position, double* variables);
bool matchRight(const ContextView& view, std::span<const PatternModule> pattern, size_t position, double* variables);
// The modules of a strict predecessor after its first, at position + 1
// onwards, exactly (nothing is skipped).
bool matchStrictTail(const ContextView& view, std::span<const PatternModule> tail, size_t position, double* variables);

} // namespace lsys
