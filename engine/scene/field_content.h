// A scene made concrete on the CPU: its terrain heightfield and every plant
// standing on it, ready for the GPU (engine/field/field_renderer.h).
#pragma once

#include "engine/scene/camera.h"
#include "engine/scene/placement.h"
#include "engine/scene/plant_models.h"
#include "engine/scene/scene.h"
#include "engine/scene/terrain.h"

#include <optional>
#include <string>

namespace pf {

// The scene's heightfield (noise or image; a noise one within `memory`) with
// its L-system's bumps added.
Heightfield terrainOf(const Scene& scene, const lsys::MemoryBudget& memory = lsys::machineMemoryBudget());

// One placement rule per species placed by density or distance (Count
// species get the distance that gives about `count` plants on the scene's
// terrain, so a grown terrain keeps their density).
std::vector<PlacementRule> placementRules(const Scene& scene);

// How a requested number of generated plants is reached.
enum class CountMode {
    NaturalDensity, // the scene's densities: the planted square, and the terrain with it, follow the count
    Densify,        // the scene's terrain: every distance scaled to fit the count on it (scaleToCount)
};

// Exactly `plants` generated plants (hand-placed ones come on top).
struct PlantCount {
    size_t plants = 0;
    CountMode mode = CountMode::NaturalDensity;
};

// The ground and every plant of the scene standing on it, grouped by species
// in scene order. Without a count, the scene as written. With one, the
// generated plants number exactly `count->plants` (placeAtNaturalDensity or
// scaleToCount); hand-placed plants are added unchanged. Same scene and count
// ⇒ same plants in the same order. Throws lsys::MemoryBudgetError (stage
// "placement") when `count` plants would not fit `memory`, before placing,
// and past it for the terrain (terrainOf).
struct PlacedField {
    Terrain terrain;         // the scene's, or grown to hold the count at natural densities
    Heightfield heightfield; // of `terrain`
    std::vector<PlantInstance> plants;
    std::string note; // set when the count could not be reached as asked (an image terrain densified)
};
PlacedField placeField(const Scene& scene, std::optional<PlantCount> count = std::nullopt,
                       const lsys::MemoryBudget& memory = lsys::machineMemoryBudget());

// What placing `plants` plants holds: a pilot placement and the kept one,
// the field's list and the content's (sorted in cluster order), saturating.
uint64_t placementBytes(uint64_t plants);

// Everything the field renderer draws, built on the CPU.
struct FieldContent {
    Scene scene; // its terrain the one the plants stand on (grown, for a natural-density count)
    Heightfield terrain;
    PlantModelPool models;
    // In cluster order (sortPlantsByCluster over clusterRoot(terrain), engine/scene/clusters.h), so
    // every tile of the field's quadtree holds a contiguous range; every user of a plant index sees this order.
    std::vector<PlantInstance> plants;
    std::string note; // PlacedField::note
};

// Terrain, plants (exactly `count` generated ones when given) and every
// species' meshes, with the models' plants when `assets` keeps them.
FieldContent buildFieldContent(const Scene& scene, std::optional<PlantCount> count = std::nullopt,
                               const ModelProgress& progress = {},
                               const lsys::MemoryBudget& memory = lsys::machineMemoryBudget(),
                               ModelAssets assets = ModelAssets::Drop);

// The plants as the GPU holds them (FieldInstance, shaders/shared/field_layouts.h),
// in content order: position and scale, yaw and wind phase, model and ids.
std::vector<gpu::FieldInstance> fieldInstancesOf(const FieldContent& content);

// A box holding the terrain and every plant, however it is turned: what a
// camera's depth range must hold (withDepthRangeFor, engine/scene/camera.h).
SceneBox fieldBox(const FieldContent& content);

} // namespace pf
