#include "lsystem/rewriting/context.h"

namespace lsys {

namespace {

bool bindIfMatches(const ContextView& view, const PatternModule& module, size_t position, double* variables) {
    if (view.string.symbols[position] != module.symbol || view.string.paramCount(position) != module.paramCount)
        return false;
    const float* parameters = view.string.paramData(position);
    for (uint16_t k = 0; k < module.paramCount; ++k) variables[module.firstVariable + k] = parameters[k];
    return true;
}

// In a ring a context that reaches an end of the string goes on from the
// other end, once per pattern module: a second time round finds nothing the
// first did not, where cpfg (generate.c) would go round for ever.
bool wrapsRound(const ContextView& view, bool& wrapped) {
    if (!view.ring || wrapped) return false;
    wrapped = true;
    return true;
}

// Whether a right context's search goes on at j: past the end only in a ring, from its first module.
bool goesOnRight(const ContextView& view, size_t& j, bool& wrapped) {
    if (j < view.string.size()) return true;
    if (!wrapsRound(view, wrapped)) return false;
    j = 0;
    return true;
}

// The ']' that ends the branch j is in (or the string's end), passing over the branches inside it.
size_t branchEnd(const ContextView& view, size_t j) {
    const size_t n = view.string.size();
    while (j < n && view.string.symbols[j] != kPop)
        j = view.string.symbols[j] == kPush ? static_cast<size_t>(view.partners[j]) + 1 : j + 1;
    return j;
}

// Matches pattern[k..] against the string from position j onwards. Recursion
// happens only at a '[' of the pattern, so its depth is bounded by the pattern.
bool matchRightFrom(const ContextView& view, std::span<const PatternModule> pattern, size_t k, size_t j,
                    double* variables) {
    const size_t n = view.string.size();
    const SymbolId* symbols = view.string.symbols.data();
    for (; k < pattern.size(); ++k) {
        const SymbolId wanted = pattern[k].symbol;
        if (wanted == kPush) {
            // The pattern enters a lateral branch: try each branch starting here.
            bool wrapped = false;
            while (goesOnRight(view, j, wrapped) && view.ignored[symbols[j]]) ++j;
            while (goesOnRight(view, j, wrapped) && symbols[j] == kPush) {
                if (matchRightFrom(view, pattern, k + 1, j + 1, variables)) return true;
                j = static_cast<size_t>(view.partners[j]) + 1;
                while (goesOnRight(view, j, wrapped) && view.ignored[symbols[j]]) ++j;
            }
            return false;
        }
        if (wanted == kSkipBranch) {
            j = branchEnd(view, j); // stopping at the branch's ']'
            continue;
        }
        if (wanted == kPop) {
            // The pattern leaves its branch: skip whatever remains of it.
            j = branchEnd(view, j);
            if (j < n) ++j;
            continue;
        }
        bool wrapped = false;
        while (true) {
            if (!goesOnRight(view, j, wrapped)) return false;
            const SymbolId symbol = symbols[j];
            if (symbol == kPush) {
                j = static_cast<size_t>(view.partners[j]) + 1; // a lateral branch the pattern does not mention
            } else if (symbol == kPop) {
                return false; // end of the branch: nothing follows on this axis
            } else if (view.ignored[symbol]) {
                ++j;
            } else {
                break;
            }
        }
        if (!bindIfMatches(view, pattern[k], j, variables)) return false;
        ++j;
    }
    return true;
}

// cpfg's right context (generate.c, RconDiff), from position j: each module
// of the pattern, '[' and ']' too, is compared with the next module that is
// neither ignored nor the start of a lateral branch (a '[' of the pattern
// meets the '[' itself); '=' goes on from the ']' that ends the branch.
bool matchRightCpfg(const ContextView& view, std::span<const PatternModule> pattern, size_t j, double* variables) {
    const SymbolId* symbols = view.string.symbols.data();
    for (const PatternModule& wanted : pattern) {
        bool wrapped = false;
        if (wanted.symbol == kSkipBranch) {
            if (goesOnRight(view, j, wrapped)) j = branchEnd(view, j);
            continue;
        }
        while (true) {
            if (!goesOnRight(view, j, wrapped)) return false;
            const SymbolId symbol = symbols[j];
            if (view.ignored[symbol])
                ++j; // brackets too, when ignored
            else if (symbol == kPush && wanted.symbol != kPush)
                j = static_cast<size_t>(view.partners[j]) + 1;
            else
                break;
        }
        if (!bindIfMatches(view, wanted, j, variables)) return false;
        ++j;
    }
    return true;
}

} // namespace

bool matchRight(const ContextView& view, std::span<const PatternModule> pattern, size_t position, double* variables) {
    if (view.cpfg) return matchRightCpfg(view, pattern, position + 1, variables);
    return matchRightFrom(view, pattern, 0, position + 1, variables);
}

bool matchStrictTail(const ContextView& view, std::span<const PatternModule> tail, size_t position, double* variables) {
    if (position + tail.size() >= view.string.size()) return false;
    for (size_t k = 0; k < tail.size(); ++k)
        if (!bindIfMatches(view, tail[k], position + 1 + k, variables)) return false;
    return true;
}

bool matchLeft(const ContextView& view, std::span<const PatternModule> pattern, size_t position, double* variables) {
    const SymbolId* symbols = view.string.symbols.data();
    ptrdiff_t j = static_cast<ptrdiff_t>(position) - 1;
    for (size_t k = pattern.size(); k-- > 0;) {
        bool wrapped = false;
        while (true) {
            if (j < 0) {
                if (!wrapsRound(view, wrapped)) return false;
                j = static_cast<ptrdiff_t>(view.string.size()) - 1; // the ring goes on from the last module
            }
            const SymbolId symbol = symbols[j];
            if (symbol == kPop) {
                const int32_t open = view.partners[j];
                if (open < 0) return false; // unmatched ']': no axis to follow
                j = open - 1;               // a whole branch before us on this axis
            } else if (symbol == kPush || view.ignored[symbol]) {
                --j; // '[': climb to the parent axis
            } else {
                break;
            }
        }
        if (!bindIfMatches(view, pattern[k], static_cast<size_t>(j), variables)) return false;
        --j;
    }
    return true;
}

} // namespace lsys
