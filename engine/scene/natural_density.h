// Exactly N generated plants at the scene's own densities (`plantfield
// --instances N`, plantbench's counts): the plants fill a square around the
// origin just large enough to hold N, and a noise terrain grows to hold that
// square when the scene's is too small (docs/FIELD.md).
#pragma once

#include "engine/scene/placement.h"
#include "engine/scene/scene.h"
#include "engine/scene/terrain.h"

#include <span>
#include <string>
#include <vector>

namespace pf {

// A noise terrain grown to `side` metres: the same noise (frequencies in
// metres, seed), so every hill keeps its size and place, and samples as far
// apart as the scene's (at most) — unless that needs more than `maxSamples`
// samples or kMaxTerrainResolution a side, then as many as that allows.
// Never smaller than `terrain`. An image terrain is returned unchanged.
Terrain grownTerrain(const Terrain& terrain, float side, size_t maxSamples);

// Height samples a grown terrain may take per requested plant (4 bytes
// each): the scene's spacing for anything denser than about a plant per
// 16 samples (2 m samples: 300 plants a hectare), a bound on the memory of
// sparse fields (trees alone), which get coarser samples instead.
inline constexpr size_t kGrownSamplesPerPlant = 16;

struct NaturalField {
    Terrain terrain;                   // the scene's, or grown
    Heightfield heightfield;           // of `terrain`
    std::vector<PlantInstance> plants; // exactly the count asked for, grouped by rule in rule order
    std::string note;                  // set when the densities could not be kept (an image terrain cannot grow)
};

// `count` plants of `rules` (placementRules of `scene`) at the densities the
// scene gives them: the scene's own placement when it holds `count`, cut to
// the `count` nearest the centre (keepCentralSquare); otherwise the same rules
// on a noise terrain grown by sqrt(count / the scene's plants) with 1 % to
// spare, cut the same way (grown again in the rare case it falls short). An
// image terrain cannot grow: its plants are densified to `count`
// (scaleToCount) and `note` says so. Throws when the rules admit no plant on
// the scene's terrain; every terrain it builds is within `memory` (terrainOf).
NaturalField placeAtNaturalDensity(const Scene& scene, std::span<const PlacementRule> rules, size_t count,
                                   uint64_t seed, const lsys::MemoryBudget& memory = lsys::machineMemoryBudget());

} // namespace pf
