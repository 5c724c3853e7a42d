// The layouts of the lists the cull pass (cull_pass.h) writes and reads,
// made on the CPU at load: the regions of the visible lists per model and
// LOD, and the chunks of plants a pass without clusters runs over
// (docs/CULLING.md). CPU only.
#pragma once

#include "shaders/field_layouts.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pf {

// The visible-list layout the cull pass appends into: for each LOD l, for
// each model m in order, a region of (instances of m) entries, so
// lists[l] = l · instanceCount + (instances of models before m) and
// lists[PLANT_MODEL_LIST_CAPACITY] = instances of m, and no list can
// overflow. Fills lists of every model from the instances' ids.x; the
// visible buffer then holds LOD_COUNT · instanceCount entries. Throws when
// an instance names a model that does not exist.
void assignVisibleLists(std::span<gpu::PlantModel> models, std::span<const gpu::FieldInstance> instances);

// Every plant of a field in chunks of CULL_GROUP_SIZE, with the near list's
// header (cluster_layouts.h): what a cull pass without clusters runs over.
std::vector<uint32_t> allPlantChunks(uint32_t instanceCount, uint32_t maxGroupsPerRow);

} // namespace pf
