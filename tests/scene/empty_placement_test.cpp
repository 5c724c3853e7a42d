// A species asked for no plant ("count": 0, "density": 0) gets none, with or
// without --instances; the other species are placed as before.
#include "scene_test_support.h"

#include "engine/scene/field_content.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace pf {
namespace {

const char* kScene = R"({
  "seed": 9,
  "terrain": { "size": 80, "resolution": 33 },
  "species": [
    { "name": "counted out", )" PF_BUSH_LSYSTEM R"(, "placement": { "count": 0 } },
    { "name": "thinned out", )" PF_BUSH_LSYSTEM R"(, "placement": { "density": 0 } },
    { "name": "tree", )" PF_BUSH_LSYSTEM R"(, "placement": { "density": 150 } }
  ]
})";

size_t plantsOf(const PlacedField& field, uint32_t species) {
    return size_t(std::count_if(field.plants.begin(), field.plants.end(),
                                [&](const PlantInstance& p) { return p.species == species; }));
}

TEST(EmptyPlacement, CountZeroAndDensityZeroPlaceNoPlant) {
    const Scene scene = loadScene(test::writeFile("empty.json", kScene));
    const PlacedField field = placeField(scene);
    EXPECT_EQ(plantsOf(field, 0), 0u);
    EXPECT_EQ(plantsOf(field, 1), 0u);
    // 150 a hectare over 0.64 ha, within Poisson sampling's spread.
    EXPECT_GT(plantsOf(field, 2), 60u);
    EXPECT_LT(plantsOf(field, 2), 130u);
}

TEST(EmptyPlacement, RequestedCountsFillOnlyTheSpeciesThatHavePlants) {
    const Scene scene = loadScene(test::writeFile("empty.json", kScene));
    for (CountMode mode : {CountMode::NaturalDensity, CountMode::Densify}) {
        const PlacedField field = placeField(scene, PlantCount{400, mode});
        EXPECT_EQ(field.plants.size(), 400u);
        EXPECT_EQ(plantsOf(field, 2), 400u);
    }
}

// A count asked of rules that admit no plant anywhere (every species above
// the terrain's heights) is the scene's fault: a SceneError, which the tools
// report as bad input (exit 2), not a failure of the program.
TEST(EmptyPlacement, ACountOfRulesThatAdmitNoPlantIsASceneError) {
    const Scene scene = loadScene(test::writeFile("nowhere.json", R"({
  "terrain": { "size": 80, "resolution": 33 },
  "species": [ { "name": "alpine", )" PF_BUSH_LSYSTEM R"(, "placement": { "height_range": [5000, 6000] } } ]
})"));
    for (CountMode mode : {CountMode::NaturalDensity, CountMode::Densify})
        EXPECT_THROW(placeField(scene, PlantCount{400, mode}), SceneError);
}

} // namespace
} // namespace pf
