#include "lsystem/context.h"

namespace lsys {

namespace {

bool bindIfMatches(const ContextView& view, const PatternModule& module, size_t position, double* variables) {
    if (view.string.symbols[position] != module.symbol || view.string.paramCount(position) != module.paramCount)
        return false;
    const float* parameters = view.string.paramData(position);
    for (uint16_t k = 0; k < module.paramCount; ++k) variables[module.firstVariable + k] = parameters[k];
    return true;
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
            while (j < n && view.ignored[symbols[j]]) ++j;
            while (j < n && symbols[j] == kPush) {
                if (matchRightFrom(view, pattern, k + 1, j + 1, variables)) return true;
                j = static_cast<size_t>(view.partners[j]) + 1;
                while (j < n && view.ignored[symbols[j]]) ++j;
            }
            return false;
        }
        if (wanted == kSkipBranch) {
            // Skip to the end of the current branch, stopping at its ']'.
            while (j < n && symbols[j] != kPop)
                j = symbols[j] == kPush ? static_cast<size_t>(view.partners[j]) + 1 : j + 1;
            continue;
        }
        if (wanted == kPop) {
            // The pattern leaves its branch: skip whatever remains of it.
            while (j < n && symbols[j] != kPop)
                j = symbols[j] == kPush ? static_cast<size_t>(view.partners[j]) + 1 : j + 1;
            if (j < n) ++j;
            continue;
        }
        while (true) {
            if (j >= n) return false;
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

} // namespace

bool matchRight(const ContextView& view, std::span<const PatternModule> pattern, size_t position, double* variables) {
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
        while (true) {
            if (j < 0) return false;
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
