#pragma once
// .ram.json files: a tree type as a ramification matrix (or Tankard 2001's
// balance and depth sliders, §3.3.1) and the growth settings of
// lsystem/ramification/ramification_generate.h. The format is in docs/RAMIFICATION.md;
// what `lsys ramify --json` prints is such a file.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lsystem/common/error.h"
#include "lsystem/ramification/ramification_generate.h"

namespace lsys {

// The largest branch budget ('max_branches', lsys ramify --max-branches): a
// budget past this would let a tree outgrow memory long before it stopped it.
inline constexpr uint64_t kMaxRamificationBranches = uint64_t(1) << 40;

// Rows a matrix may have: a tree of depth 64 would hold at least 2^63 branches.
inline constexpr uint32_t kMaxRamificationOrders = 64;

struct RamificationFile {
    std::optional<RamificationTree> tree; // none when there are diagnostics
    std::vector<Diagnostic> diagnostics;  // the first problem, at its file:line:column
    std::string source;                   // the text, for formatDiagnostics
};

// Whether a path names a .ram.json file rather than a plant.
bool isRamificationFile(const std::filesystem::path& path);

RamificationFile readRamificationFile(const std::filesystem::path& path);
// The same from text; `file` names it in diagnostics.
RamificationFile parseRamification(std::string text, const std::string& file);

} // namespace lsys
