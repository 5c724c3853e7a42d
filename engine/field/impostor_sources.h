// Which model's impostor frames each model shows (CPU): its own while every
// model's rings of frames fit the device's image array layers; past that,
// the variants of a species share the frames of a few of them, so a field
// of more variants than the atlas holds still renders (docs/IMPOSTORS.md,
// "Sharing frames").
#pragma once

#include "engine/scene/plant_models.h"

#include <cstdint>
#include <vector>

namespace pf {

// Per model of `pool`, the model whose frames it shows. With every model
// within `modelCapacity` (the layers one model's frames take into the
// device's limit), each shows its own. Else species s keeps frames for
// k_s = max(1, ⌊V_s·capacity/models⌋) of its V_s variants (the largest k_s
// lowered until they fit) and variant v shows those of variant v mod k_s.
// Throws SceneError naming the first species left without frames and the
// capacity when the pool has more species than `modelCapacity`.
std::vector<uint32_t> impostorSources(const PlantModelPool& pool, uint32_t modelCapacity);

} // namespace pf
