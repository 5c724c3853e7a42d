#pragma once
// Context matching with lpfg's bracket rules, or with cpfg's.
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
//
// cpfg's rules (Grammar::cpfgContexts; cpfg generate.c, RconDiff and
// LconDiff) differ in the right context only. The pattern is read module for
// module, each after the ignored modules and the lateral branches before it:
// a '[' of the pattern must be the next module, so it enters the first
// lateral branch only, and a ']' must be, so the branch has to end right
// after the modules the pattern names ('=' skips the rest of a branch). An
// ignored '[' or ']' (consider: without brackets) is read past like any
// ignored module, so the context runs on into a branch or out of one. The
// left context skips branches and climbs at '[' whatever is ignored, as
// lpfg's does, and a bracket in its pattern never matches: the walk never
// stops on one.
//
// Ring L-systems (cpfg generate.c, LconDiff and RconDiff): the string's ends
// are joined, so a left context that reaches the start goes on from the last
// module and a right context that reaches the end goes on from the first,
// skipping brackets and ignored symbols there as anywhere. A context may come
// round onto the module itself, and a long one round the ring more than once.
// Where cpfg would go round for ever (no module of the ring can be read, all
// ignored or in branches) the context does not match.

#include <cstdint>
#include <span>

#include "lsystem/language/grammar.h"
#include "lsystem/language/module_string.h"

namespace lsys {

struct ContextView {
    const ModuleString& string;
    const int32_t* partners; // computeBracketPartners of string
    const uint8_t* ignored;  // per symbol
    bool ring = false;       // Grammar::ring
    bool cpfg = false;       // Grammar::cpfgContexts
};

// On success the parameters of the context modules are written to variables
// at each pattern module's firstVariable.
bool matchLeft(const ContextView& view, std::span<const PatternModule> pattern, size_t position, double* variables);
bool matchRight(const ContextView& view, std::span<const PatternModule> pattern, size_t position, double* variables);
// The modules of a strict predecessor after its first, at position + 1
// onwards, exactly (nothing is skipped).
bool matchStrictTail(const ContextView& view, std::span<const PatternModule> tail, size_t position, double* variables);

} // namespace lsys
