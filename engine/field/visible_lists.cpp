#include "engine/field/visible_lists.h"

#include "shaders/shared/cluster_layouts.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pf {

void assignVisibleLists(std::span<gpu::PlantModel> models, std::span<const gpu::FieldInstance> instances) {
    std::vector<uint32_t> perModel(models.size(), 0);
    for (const gpu::FieldInstance& inst : instances) {
        if (inst.ids.x >= models.size())
            throw std::runtime_error("field instance refers to model " + std::to_string(inst.ids.x) + " of " +
                                     std::to_string(models.size()));
        ++perModel[inst.ids.x];
    }
    const uint32_t total = uint32_t(instances.size());
    uint32_t first = 0;
    for (size_t m = 0; m < models.size(); ++m) {
        for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) models[m].lists[lod] = lod * total + first;
        models[m].lists[PLANT_MODEL_LIST_CAPACITY] = perModel[m];
        first += perModel[m];
    }
}

FieldPlants fieldPlantsOf(FieldContent& content) {
    PlantModelPool& pool = content.models;
    FieldPlants plants;
    plants.instances = fieldInstancesOf(content);
    for (const PlantModelInfo& info : pool.models) plants.models.push_back(info.gpu);
    assignVisibleLists(plants.models, plants.instances);
    for (size_t m = 0; m < pool.models.size(); ++m) pool.models[m].gpu.lists = plants.models[m].lists;
    return plants;
}

std::vector<uint32_t> naiveVisibleList(uint32_t plantCount) {
    std::vector<uint32_t> naive(plantCount);
    for (uint32_t i = 0; i < plantCount; ++i) naive[i] = i | (VISIBLE_COVERAGE_MAX << VISIBLE_COVERAGE_SHIFT);
    return naive;
}

std::vector<uint32_t> allPlantChunks(uint32_t instanceCount, uint32_t maxGroupsPerRow) {
    const uint32_t chunks = (instanceCount + CULL_GROUP_SIZE - 1) / CULL_GROUP_SIZE;
    const uint32_t row = std::min(chunks, maxGroupsPerRow);
    std::vector<uint32_t> words = {chunks, row, row ? (chunks + row - 1) / row : 0, 1};
    for (uint32_t c = 0; c < chunks; ++c) {
        words.push_back(c * CULL_GROUP_SIZE);
        words.push_back(std::min<uint32_t>(instanceCount - c * CULL_GROUP_SIZE, CULL_GROUP_SIZE));
    }
    return words;
}

} // namespace pf
