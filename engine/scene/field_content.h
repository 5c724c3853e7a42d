// A scene made concrete on the CPU: its terrain heightfield and every plant
// standing on it, ready for the GPU (engine/field/field_renderer.h).
#pragma once

#include "engine/scene/placement.h"
#include "engine/scene/plant_models.h"
#include "engine/scene/scene.h"
#include "engine/scene/terrain.h"

#include <optional>

namespace pf {

// The scene's heightfield (noise or image).
Heightfield terrainOf(const Scene& scene);

// One placement rule per species placed by density or distance (Count
// species get the distance that gives about `count` plants on the terrain).
std::vector<PlacementRule> placementRules(const Scene& scene);

// Every plant of the scene, grouped by species in scene order. With
// `count`, all generated plants together are scaled to exactly `count`
// (scaleToCount) — explicit ones are added unchanged on top. Same scene and
// count ⇒ same plants in the same order.
std::vector<PlantInstance> placePlants(const Scene& scene, const Heightfield& terrain,
                                       std::optional<size_t> count = std::nullopt);

// Everything the field renderer draws, built on the CPU.
struct FieldContent {
    Scene scene;
    Heightfield terrain;
    PlantModelPool models;
    std::vector<PlantInstance> plants;
};

// Terrain, plants (scaled to `count` when given) and every species' meshes.
FieldContent buildFieldContent(const Scene& scene, std::optional<size_t> count = std::nullopt,
                               const ModelProgress& progress = {});

} // namespace pf
