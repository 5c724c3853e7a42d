// impostorSources (engine/field/impostor_sources.h): every model shows its
// own frames while the atlas holds them all; past that, variants of a
// species share, never across species; more species than the atlas holds
// are refused, naming the species and the capacity.
#include "engine/field/impostor_sources.h"
#include "engine/scene/scene.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace pf {
namespace {

// A pool of `variants[s]` models for each species s, named as buildPlantModels names them.
PlantModelPool poolOf(std::initializer_list<uint32_t> variants) {
    PlantModelPool pool;
    uint32_t species = 0;
    for (const uint32_t count : variants) {
        pool.firstModel.push_back(uint32_t(pool.models.size()));
        for (uint32_t v = 0; v < count; ++v) {
            PlantModelInfo model;
            model.species = species;
            model.variant = v;
            model.name = "species" + std::to_string(species) + "#" + std::to_string(v);
            pool.models.push_back(model);
        }
        ++species;
    }
    return pool;
}

TEST(ImpostorSources, EveryModelShowsItsOwnWhileTheAtlasHoldsThemAll) {
    const std::vector<uint32_t> sources = impostorSources(poolOf({3, 2, 4}), 9);
    for (uint32_t m = 0; m < sources.size(); ++m) EXPECT_EQ(sources[m], m);
}

TEST(ImpostorSources, VariantsPastTheCapacityShareWithinTheirSpecies) {
    const PlantModelPool pool = poolOf({171, 1});
    const std::vector<uint32_t> sources = impostorSources(pool, 56);
    std::set<uint32_t> baked;
    for (uint32_t m = 0; m < sources.size(); ++m) {
        EXPECT_LE(sources[m], m);
        EXPECT_EQ(pool.models[sources[m]].species, pool.models[m].species) << m;
        EXPECT_EQ(sources[sources[m]], sources[m]) << "a source shows its own frames";
        baked.insert(sources[m]);
    }
    EXPECT_LE(baked.size(), 56u);
    EXPECT_EQ(sources[171], 171u) << "the one-variant species keeps its own";
    EXPECT_GT(baked.size(), 50u) << "the capacity is used";
}

TEST(ImpostorSources, MoreSpeciesThanTheAtlasHoldsAreRefusedNamingTheSpecies) {
    try {
        impostorSources(poolOf({1, 1, 1, 1}), 3);
        FAIL() << "four species fitted an atlas of three models";
    } catch (const SceneError& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("at most 3 plant models"), std::string::npos) << what;
        EXPECT_NE(what.find("species \"species3\""), std::string::npos) << what;
    }
}

} // namespace
} // namespace pf
