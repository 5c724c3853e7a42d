// Exactly N plants at the scene's own densities: a central square of the
// scene's placement for fewer, a grown noise terrain for more, densified on
// an image terrain that cannot grow; --densify keeps the old scaling.
#include "scene_test_support.h"

#include "engine/image/image.h"
#include "engine/scene/field_content.h"
#include "engine/scene/natural_density.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// 100 m of gentle hills (spacing 100/64 m), a tree rule with a clearance, a
// bush rule under it and two hand-placed bushes.
const char* kForest = R"({
  "seed": 4,
  "terrain": { "size": 100, "resolution": 65, "noise": { "octaves": 3, "amplitude": 3, "frequency": 0.02 } },
  "species": [
    { "name": "tree", )" PF_BUSH_LSYSTEM R"(, "placement": { "density": 100, "clearance": 2 } },
    { "name": "bush", )" PF_BUSH_LSYSTEM R"(, "placement": { "density": 900, "max_slope": 30 } },
    { "name": "planted", )" PF_BUSH_LSYSTEM R"(,
      "placement": { "instances": [ { "position": [3, 4] }, { "position": [-20, 10], "scale": 2 } ] } }
  ]
})";

Scene forest() { return loadScene(test::writeFile("forest.json", kForest)); }

size_t generatedOf(const Scene& scene, const std::vector<PlantInstance>& plants) {
    return size_t(std::count_if(plants.begin(), plants.end(), [&](const PlantInstance& p) {
        return scene.species[p.species].placement.mode != PlacementMode::Explicit;
    }));
}

float maxNorm(const PlantInstance& p) { return std::max(std::abs(p.position.x), std::abs(p.position.z)); }

// Generated plants inside the square |x|, |z| ≤ half.
size_t generatedWithin(const Scene& scene, const std::vector<PlantInstance>& plants, float half) {
    return size_t(std::count_if(plants.begin(), plants.end(), [&](const PlantInstance& p) {
        return scene.species[p.species].placement.mode != PlacementMode::Explicit && maxNorm(p) <= half;
    }));
}

TEST(NaturalDensity, AsManyAsTheSceneHoldsGivesTheSceneAsWritten) {
    const Scene scene = forest();
    const PlacedField written = placeField(scene);
    const PlacedField counted = placeField(scene, PlantCount{generatedOf(scene, written.plants)});
    EXPECT_EQ(counted.terrain, scene.terrain);
    ASSERT_EQ(counted.plants.size(), written.plants.size());
    for (size_t i = 0; i < written.plants.size(); ++i)
        EXPECT_EQ(counted.plants[i].position, written.plants[i].position);
    EXPECT_TRUE(counted.note.empty());
}

TEST(NaturalDensity, FewerPlantsFillACentralSquareOfTheScenesField) {
    const Scene scene = forest();
    const PlacedField written = placeField(scene);
    const size_t natural = generatedOf(scene, written.plants);
    ASSERT_GT(natural, 800u);
    const size_t count = natural / 4;
    const PlacedField field = placeField(scene, PlantCount{count});
    EXPECT_EQ(field.terrain, scene.terrain);
    EXPECT_EQ(generatedOf(scene, field.plants), count);
    // A quarter of the plants: a square of about half the side, at the scene's density.
    for (const PlantInstance& p : field.plants)
        EXPECT_TRUE(scene.species[p.species].placement.mode == PlacementMode::Explicit ||
                    maxNorm(p) <= 0.25f * 100 * 1.15f)
            << p.position.x << ", " << p.position.z;
    // And they are the scene's own plants there, not a thinned field.
    for (const PlantInstance& p : field.plants)
        EXPECT_TRUE(std::any_of(written.plants.begin(), written.plants.end(), [&](const PlantInstance& w) {
            return w.position == p.position && w.species == p.species;
        }));
    // Every species keeps its share.
    for (uint32_t s = 0; s < 2; ++s) {
        const auto ofSpecies = [&](const std::vector<PlantInstance>& v) {
            return double(std::count_if(v.begin(), v.end(), [&](const PlantInstance& p) { return p.species == s; }));
        };
        EXPECT_NEAR(ofSpecies(field.plants) / double(count), ofSpecies(written.plants) / double(natural), 0.05) << s;
    }
}

TEST(NaturalDensity, MorePlantsGrowTheNoiseTerrainKeepingItsSpacingAndHills) {
    const Scene scene = forest();
    const PlacedField written = placeField(scene);
    const size_t natural = generatedOf(scene, written.plants);
    const size_t count = natural * 4;
    const PlacedField field = placeField(scene, PlantCount{count});
    EXPECT_EQ(generatedOf(scene, field.plants), count);
    // Four times the plants on about four times the area.
    EXPECT_GT(field.terrain.size, 1.9f * scene.terrain.size);
    EXPECT_LT(field.terrain.size, 2.2f * scene.terrain.size);
    EXPECT_EQ(field.heightfield.size, field.terrain.size);
    EXPECT_EQ(field.heightfield.resolution, field.terrain.resolution);
    const float spacing = scene.terrain.size / float(scene.terrain.resolution - 1);
    EXPECT_LE(field.heightfield.spacing(), spacing);
    EXPECT_GT(field.heightfield.spacing(), 0.97f * spacing);
    // The same hills in the same places: heights agree across the scene's square.
    const Heightfield own = terrainOf(scene);
    for (float x = -50; x <= 50; x += 7.3f)
        for (float z = -50; z <= 50; z += 6.1f)
            EXPECT_NEAR(heightAt(field.heightfield, x, z), heightAt(own, x, z), 0.15f);
    // The scene's own square holds about as many plants as the scene gives it.
    EXPECT_NEAR(double(generatedWithin(scene, field.plants, 50)), double(natural), 0.1 * double(natural));
    // Hand-placed plants stay where they were.
    for (const PlantInstance& p : field.plants)
        EXPECT_TRUE(p.species != 2 || p.position.x == 3.0f || p.position.x == -20.0f);
    EXPECT_EQ(field.plants.size() - generatedOf(scene, field.plants), 2u);
}

TEST(NaturalDensity, CountsAreExactAndTheSameEveryTime) {
    const Scene scene = forest();
    for (size_t count : {1u, 37u, 1000u, 2500u, 6000u}) {
        const PlacedField a = placeField(scene, PlantCount{count});
        const PlacedField b = placeField(scene, PlantCount{count});
        EXPECT_EQ(generatedOf(scene, a.plants), count);
        ASSERT_EQ(a.plants.size(), b.plants.size());
        for (size_t i = 0; i < a.plants.size(); ++i) ASSERT_EQ(a.plants[i].position, b.plants[i].position) << count;
        // Grouped by species in scene order.
        EXPECT_TRUE(
            std::is_sorted(a.plants.begin(), a.plants.end(),
                           [](const PlantInstance& l, const PlantInstance& r) { return l.species < r.species; }));
    }
}

TEST(NaturalDensity, CountSpeciesKeepTheirDensityOnAGrownTerrain) {
    const Scene scene = loadScene(std::string(PLANTFIELD_DATA_DIR) + "/scenes/test_small.json"); // 20 bushes on 40 m
    const PlacedField field = placeField(scene, PlantCount{200});
    EXPECT_EQ(generatedOf(scene, field.plants), 200u);
    EXPECT_GT(field.terrain.size, 2.8f * scene.terrain.size);
    EXPECT_NEAR(double(generatedWithin(scene, field.plants, 20)), 20.0, 6.0);
}

TEST(NaturalDensity, DensifyKeepsTheScenesTerrainAndScalesTheDistances) {
    const Scene scene = forest();
    const PlacedField field = placeField(scene, PlantCount{5000, CountMode::Densify});
    EXPECT_EQ(field.terrain, scene.terrain);
    const std::vector<PlantInstance> scaled =
        scaleToCount(terrainOf(scene), placementRules(scene), 5000, placementSeed(scene, 0));
    ASSERT_EQ(generatedOf(scene, field.plants), scaled.size());
    for (size_t i = 0; i < scaled.size(); ++i) ASSERT_EQ(field.plants[i].position, scaled[i].position);
}

TEST(NaturalDensity, AnImageTerrainCannotGrowSoItIsDensifiedWithANote) {
    RgbaImage image{33, 33, std::vector<uint8_t>(33 * 33 * 4, 255)};
    for (size_t i = 0; i < 33 * 33; ++i)
        image.pixels[i * 4] = image.pixels[i * 4 + 1] = image.pixels[i * 4 + 2] = uint8_t(i % 7);
    const auto png = test::testFolder() / "ground.png";
    writePng(png.string(), image);
    const Scene scene = loadScene(test::writeFile("image.json", R"({
      "terrain": { "size": 60, "image": { "path": "ground.png", "height_scale": 2 } },
      "species": [ { "name": "bush", )" PF_BUSH_LSYSTEM R"(, "placement": { "density": 500 } } ]
    })"));
    const size_t natural = placeField(scene).plants.size();
    const PlacedField fewer = placeField(scene, PlantCount{natural / 2});
    EXPECT_EQ(fewer.plants.size(), natural / 2);
    EXPECT_TRUE(fewer.note.empty()) << "fewer plants keep the densities on any terrain";
    const PlacedField more = placeField(scene, PlantCount{natural * 3});
    EXPECT_EQ(more.plants.size(), natural * 3);
    EXPECT_EQ(more.terrain, scene.terrain);
    EXPECT_NE(more.note.find("image terrain cannot grow"), std::string::npos) << more.note;
    EXPECT_NE(more.note.find("densified"), std::string::npos) << more.note;
}

TEST(NaturalDensity, RulesThatAdmitNoPlantFail) {
    const Scene scene = loadScene(test::writeFile("none.json", R"({
      "terrain": { "size": 50, "resolution": 9, "noise": { "amplitude": 0 } },
      "species": [ { "name": "bush", )" PF_BUSH_LSYSTEM R"(, "placement": { "density": 500, "height_range": [5, 9] } } ]
    })"));
    EXPECT_THROW(placeField(scene, PlantCount{10}), std::runtime_error);
}

TEST(GrownTerrain, KeepsTheSpacingWithinTheSampleBudget) {
    Terrain terrain; // 512 m, 257 samples: 2 m apart
    EXPECT_EQ(grownTerrain(terrain, 1000, size_t(1) << 30).resolution, 501u);
    EXPECT_EQ(grownTerrain(terrain, 1000, size_t(1) << 30).size, 1000.0f);
    EXPECT_EQ(grownTerrain(terrain, 1001, size_t(1) << 30).resolution, 502u); // never coarser than 2 m
    // A budget of 300² samples, and never more than kMaxTerrainResolution a side.
    EXPECT_EQ(grownTerrain(terrain, 1000, 300 * 300).resolution, 300u);
    EXPECT_EQ(grownTerrain(terrain, 1e6f, size_t(1) << 40).resolution, kMaxTerrainResolution);
    // Never fewer samples than the scene's, never smaller.
    EXPECT_EQ(grownTerrain(terrain, 1000, 10).resolution, 257u);
    EXPECT_EQ(grownTerrain(terrain, 100, size_t(1) << 30), terrain);
    // An image gives its own samples: unchanged.
    Terrain image = terrain;
    image.heightfield = ImageHeightfield{"x.png", 5};
    EXPECT_EQ(grownTerrain(image, 1000, size_t(1) << 30), image);
}

TEST(KeepCentralSquare, KeepsTheNearestInTheMaximumNormInTheirOrder) {
    std::vector<PlantInstance> plants;
    for (float x : {9.0f, -1.0f, 4.0f, 0.5f, -7.0f, 2.0f}) plants.push_back(PlantInstance{{x, 0.0f, -0.5f * x}});
    const std::vector<PlantInstance> kept = keepCentralSquare(plants, 3);
    ASSERT_EQ(kept.size(), 3u);
    EXPECT_EQ(kept[0].position.x, -1.0f);
    EXPECT_EQ(kept[1].position.x, 0.5f);
    EXPECT_EQ(kept[2].position.x, 2.0f);
    EXPECT_EQ(keepCentralSquare(plants, 10).size(), plants.size());
    EXPECT_TRUE(keepCentralSquare(plants, 0).empty());
}

TEST(NaturalDensity, ACountPastTheMemoryBudgetIsRefusedBeforePlacing) {
    const Scene scene = forest();
    try {
        placeField(scene, PlantCount{10'000'000}, {64ull << 20});
        FAIL() << "expected the placement to be refused";
    } catch (const lsys::MemoryBudgetError& error) {
        EXPECT_NE(std::string(error.what()).find("placement needs " + lsys::formatBytes(placementBytes(10'000'000))),
                  std::string::npos)
            << error.what();
    }
    // The scene's own terrain is checked with the same budget: "resolution": 8000 is valid.
    Scene fine = scene;
    fine.terrain.resolution = 8000;
    EXPECT_THROW(placeField(fine, std::nullopt, {256ull << 20}), lsys::MemoryBudgetError);
}

} // namespace
} // namespace pf
