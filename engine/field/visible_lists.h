// The layouts of the lists the cull pass (cull_pass.h) writes and the draw
// shaders read, made on the CPU at load: the regions of the visible lists
// per model and LOD, the plants as the GPU reads them with their models'
// lists, the naive baseline's list of every plant, and the chunks of
// plants a pass without clusters runs over (docs/CULLING.md). CPU only.
#pragma once

#include "engine/scene/field_content.h"
#include "shaders/shared/field_layouts.h"

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

// The plants as the passes read them: one instance per plant
// (fieldInstancesOf) and every model with its visible lists assigned.
struct FieldPlants {
    std::vector<gpu::FieldInstance> instances;
    std::vector<gpu::PlantModel> models;
};
// Also writes each model's lists into `content.models` (PlantModelInfo::gpu),
// where the draw templates read them.
FieldPlants fieldPlantsOf(FieldContent& content);

// The naive baseline's visible list: entry i is plant i at full coverage.
std::vector<uint32_t> naiveVisibleList(uint32_t plantCount);

// Every plant of a field in chunks of CULL_GROUP_SIZE, with the near list's
// header (cluster_layouts.h): what a cull pass without clusters runs over.
std::vector<uint32_t> allPlantChunks(uint32_t instanceCount, uint32_t maxGroupsPerRow);

} // namespace pf
