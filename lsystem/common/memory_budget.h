#pragma once
// One memory budget for every stage that can grow with its input:
// derivation, turtle, b-grammar and instance graph, export, terrain, the
// field's plants and what is uploaded to the GPU. Each stage works out what
// it is about to allocate from the counts it already has and calls need()
// first, so a request past the budget is an error naming the stage, the need
// and the limit rather than a std::bad_alloc (or the kernel's OOM killer)
// halfway through. Counts are multiplied and added saturating at UINT64_MAX,
// so a need too large to count is still refused.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "lsystem/common/error.h"

namespace lsys {

struct MemoryBudget {
    uint64_t limitBytes = UINT64_MAX;
};

// Raised by need(); a DerivationError, so every tool's catch sites print it
// and exit 2.
struct MemoryBudgetError : DerivationError {
    using DerivationError::DerivationError;
};

// 3/4 of the smallest of the available memory, the cgroup memory limit and
// RLIMIT_AS/RLIMIT_DATA, each less what is used (machine_memory.h), or
// kFallbackMemoryBudget where none can be read.
inline constexpr uint64_t kFallbackMemoryBudget = 4ull << 30;
MemoryBudget machineMemoryBudget();

// Throws MemoryBudgetError, "memory budget: STAGE needs 265.7 GiB, the limit
// is 5.4 GiB (set with --memory-budget)", when bytes > budget.limitBytes.
void need(const MemoryBudget& budget, std::string_view stage, uint64_t bytes);

// Saturating arithmetic for byte counts.
uint64_t bytesTimes(uint64_t count, uint64_t bytesEach);
uint64_t bytesPlus(uint64_t a, uint64_t b);

// "800 B", "12.0 MiB", "1.5 GiB": binary units (as --memory-budget reads them), one decimal.
std::string formatBytes(uint64_t bytes);

// A size as given to --memory-budget: plain bytes or a number with K, M, G or
// T (binary: 512M is 512 MiB; "MB", "MiB", "GB" … are read alike, in any case),
// e.g. "4G", "1.5G", "800000000". nullopt for anything else, zero, or a size
// past 2^64.
std::optional<uint64_t> parseByteSize(std::string_view text);

} // namespace lsys
