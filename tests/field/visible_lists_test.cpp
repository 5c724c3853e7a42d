// The visible-list layout the renderer uploads and the cull pass appends into
// (assignVisibleLists): every (model, LOD) list has room for all plants of
// its model, and no two lists share an entry.
#include "engine/field/visible_lists.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace {

std::vector<gpu::FieldInstance> instancesOfModels(const std::vector<uint32_t>& modelOfInstance) {
    std::vector<gpu::FieldInstance> instances(modelOfInstance.size());
    for (size_t i = 0; i < instances.size(); ++i) instances[i].ids = glm::uvec4(modelOfInstance[i], 0, 0, 0);
    return instances;
}

TEST(VisibleLists, EveryListHoldsAllPlantsOfItsModelAndNoListsOverlap) {
    const std::vector<uint32_t> modelOf = {2, 0, 2, 2, 1, 0, 2, 4, 2}; // model 3 has no plant
    std::vector<gpu::PlantModel> models(5);
    const std::vector<gpu::FieldInstance> instances = instancesOfModels(modelOf);
    pf::assignVisibleLists(models, instances);

    const uint32_t entries = LOD_COUNT * uint32_t(instances.size());
    std::vector<int> owner(entries, -1);
    for (uint32_t m = 0; m < models.size(); ++m) {
        uint32_t plants = 0;
        for (uint32_t model : modelOf) plants += model == m;
        EXPECT_EQ(models[m].lists[PLANT_MODEL_LIST_CAPACITY], plants) << "model " << m;
        for (uint32_t lod = 0; lod < LOD_COUNT; ++lod)
            for (uint32_t k = 0; k < plants; ++k) {
                const uint32_t entry = models[m].lists[lod] + k;
                ASSERT_LT(entry, entries) << "model " << m << " LOD " << lod;
                EXPECT_EQ(owner[entry], -1) << "entry " << entry << " of model " << m << " LOD " << lod;
                owner[entry] = int(m * LOD_COUNT + lod);
            }
    }
    for (uint32_t entry = 0; entry < entries; ++entry) EXPECT_NE(owner[entry], -1) << "entry " << entry << " unused";
}

TEST(VisibleLists, ListsOfOneLodAreContiguousInModelOrder) {
    std::vector<gpu::PlantModel> models(3);
    pf::assignVisibleLists(models, instancesOfModels({1, 0, 1, 2, 2, 2}));
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) {
        EXPECT_EQ(models[0].lists[lod], lod * 6);
        EXPECT_EQ(models[1].lists[lod], lod * 6 + 1);
        EXPECT_EQ(models[2].lists[lod], lod * 6 + 3);
    }
}

TEST(VisibleLists, InstanceOfAMissingModelIsAnError) {
    std::vector<gpu::PlantModel> models(2);
    EXPECT_THROW(pf::assignVisibleLists(models, instancesOfModels({0, 2})), std::runtime_error);
}

} // namespace
