#pragma once
// L-system mountains (the clouds-and-mountains chapter, §21–22;
// docs/TERRAIN_LSYSTEMS.md): the turtle walks a derived word as it does for
// a plant, and each mountain module — Hill, Peak, Mesa, Valley — leaves a
// bump (lsystem/landscape/terrain_bumps.h) centred at the turtle's x and z,
// as high as the turtle is above its start and as wide as the turtle's width.
//
// The turtle starts at the origin lying on the ground: heading along +x turned
// counter-clockwise (seen from above) by the placement's heading, up +y, so
// `F` walks the horizontal core, `+`/`-` turn it on the ground and `^`/`&`
// send a branch up or down. Every other module is the plant turtle's command
// (lsystem/turtle/turtle.h), the width `!` included.

#include <cstdint>
#include <optional>
#include <vector>

#include "lsystem/common/error.h"
#include "lsystem/common/memory_budget.h"
#include "lsystem/landscape/terrain_bumps.h"
#include "lsystem/language/grammar.h"
#include "lsystem/language/module_string.h"
#include "lsystem/turtle/turtle.h"

namespace lsys::landscape {

// The most bumps one L-system may make: the extreme-peak check compares
// every bump with every other (4096² ≈ 17 million evaluations).
inline constexpr uint32_t kMaxMountainBumps = 4096;
// The most modules a mountain word may grow to while it is derived.
inline constexpr size_t kMaxMountainModules = 1'000'000;

// Where the turtle's plant space lands in the terrain.
struct MountainPlacement {
    float originX = 0.0f, originZ = 0.0f; // metres: the turtle's start
    float headingDegrees = 0.0f;          // the start heading, counter-clockwise from +x seen from above
    float scale = 10.0f;                  // metres per turtle unit, across and up alike
    // The chapter's extreme peaks: the superimposed height at any bump's
    // centre may not pass ±maxHeight metres.
    float maxHeight = 200.0f;
    uint32_t maxBumps = kMaxMountainBumps;
};

// The bumps of a derived (and interpreted) word, in the word's order, with
// the turtle of `settings` started as the header comment says. Hill, Peak,
// Mesa and Valley take up to two parameters: a factor on the height (the
// turtle's height above its start times scale; negated for Valley) and a
// factor on the radius (half the turtle's width times scale), both 1 when
// left out. Throws MountainError (naming the module, its place in the word
// and the turtle's position) past the placement's limits, and
// MemoryBudgetError (stage "turtle") when what the turtle would hold
// (turtleBytes) is past `memory`.
std::vector<TerrainBump> mountainBumps(const ModuleString& word, const SymbolTable& symbols,
                                       const TurtleSettings& settings, const MountainPlacement& placement,
                                       const MemoryBudget& memory = machineMemoryBudget());

// Derives the grammar (with `seed` in place of its own when given, within
// kMaxMountainModules and `memory`), applies its interpretation rules and
// returns mountainBumps with the header's turtle settings.
std::vector<TerrainBump> mountainBumpsOf(const Grammar& grammar, const MountainPlacement& placement,
                                         std::optional<uint64_t> seed = std::nullopt,
                                         const MemoryBudget& memory = machineMemoryBudget());

} // namespace lsys::landscape
