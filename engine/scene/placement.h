// Plant placement over a terrain: seeded Poisson-disk sampling (Bridson) per
// species, with slope and height limits and clearance between species.
// Algorithms and guarantees: docs/FIELD.md.
#pragma once

#include "engine/scene/terrain.h"
#include "lsystem/common/memory_budget.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace pf {

// One plant of the field. Plain data; the GPU layout is declared separately.
struct PlantInstance {
    glm::vec3 position{}; // on the terrain surface
    float rotation = 0;   // yaw about +y, radians in [0, 2π)
    float scale = 1;
    uint32_t species = 0;
    uint32_t variant = 0; // in [0, variants) of the rule that placed it
    float windPhase = 0;  // radians in [0, 2π)
};

struct PlacementRule {
    uint32_t species = 0;        // copied into every instance the rule places
    float densityPerHectare = 0; // plants per 10 000 m²; when > 0 it sets the distance (poissonDistanceForDensity)
    float minDistance = 1;       // metres between two plants of this rule, used when densityPerHectare is 0
    float clearance = 0;         // metres kept free of other rules' plants; a pair keeps the larger of their two
    float maxSlopeDegrees = 90;
    float minHeight = std::numeric_limits<float>::lowest();
    float maxHeight = std::numeric_limits<float>::max();
    float minScale = 1, maxScale = 1;
    uint32_t variants = 1;
    uint64_t seed = 0; // mixed into the placement seed for this rule's streams (a scene's per-species seed)
};

// Bridson's sampling packs about 0.616/r² points per unit area for distance r
// (measured; docs/FIELD.md), so the distance for a density d per hectare is
// r = sqrt(10000 / d) · √0.616.
inline constexpr float kPoissonPackingFactor = 0.785f;
float poissonDistanceForDensity(float plantsPerHectare);
// The distance a rule keeps between its own plants, from its density if set.
float ruleDistance(const PlacementRule& rule);

// All plants of one rule. Same (terrain, rule, seed) ⇒ same instances in the
// same order. Throws on an invalid rule.
std::vector<PlantInstance> placePoissonDisk(const Heightfield& terrain, const PlacementRule& rule, uint64_t seed);

// Several rules on one terrain: rules are sampled from the largest distance to
// the smallest, and a plant is kept only where it stands at least
// max(clearanceA, clearanceB) from every plant of the rules sampled before it.
// Output is grouped by rule, in the order of `rules`. Throws
// lsys::MemoryBudgetError (stage "placement") before sampling when what the
// rules' distances ask for, placementSamplingBytes, would not fit `memory`.
std::vector<PlantInstance> placeSpecies(const Heightfield& terrain, std::span<const PlacementRule> rules, uint64_t seed,
                                        const lsys::MemoryBudget& memory = {});
// At most what sampling the rules takes on `terrain`, from their distances
// alone: each rule's two grids of cells, and as many plants as open flat
// ground holds at its distance, with their instances.
uint64_t placementSamplingBytes(const Heightfield& terrain, std::span<const PlacementRule> rules);

// Exactly `count` plants for the same rules (`plantfield --instances N` must
// render exactly N): the rules with every distance and clearance scaled by one
// factor, chosen from a small pilot placement to give slightly more than
// `count`, then thinned to `count` by keeping the plants with the smallest hash
// of (seed, position in the placement) — a uniform subset of a few per cent, so
// every species keeps its share and the field stays a Poisson-disk field.
// Throws when the rules admit no plant at all on this terrain.
std::vector<PlantInstance> scaleToCount(const Heightfield& terrain, std::span<const PlacementRule> rules, size_t count,
                                        uint64_t seed);

// The `count` plants nearest the terrain's centre in the maximum norm, so
// they fill a square around the origin at the density they were placed
// with; in their given order (grouping by rule survives). All of them when
// there are no more than `count`.
std::vector<PlantInstance> keepCentralSquare(const std::vector<PlantInstance>& plants, size_t count);

} // namespace pf
