#include "fuzz_targets.h"

#include "lsystem/common/error.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/ramification/ramification_file.h"
#include "lsystem/ramification/ramification_generate.h"

#include <algorithm>
#include <string>

namespace pf::fuzz {

void runRamificationInput(const uint8_t* data, size_t size) {
    lsys::RamificationFile file =
        lsys::parseRamification(std::string(reinterpret_cast<const char*>(data), size), "fuzz.ram.json");
    if (!file.tree) return; // a located diagnostic is the right outcome
    // Bounded work per input: a file may allow a million branches, and each
    // foliage cluster up to 64 × 64 leaves (2 000 branches made 312 000 leaves,
    // 14 s to draw in the release build: heavy, not stuck).
    file.tree->maxBranches = std::min<uint64_t>(file.tree->maxBranches, 500);
    try {
        const lsys::GeneratedTree tree = lsys::generateTree(*file.tree);
        (void)lsys::plantOf(tree, lsys::MemoryBudget{64ull << 20});
    } catch (const lsys::DerivationError&) {
        // The tree past its branch budget: a clear error.
    } catch (const lsys::MemoryBudgetError&) {
        // A plant refused, before it is drawn, for the memory it would take.
    }
}

} // namespace pf::fuzz
