// Scene files that load: the shipped scenes, defaults, a fully specified
// scene, inheritance of the global placement, paths and seeds.
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

namespace pf {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(PLANTFIELD_DATA_DIR) / "scenes";
const std::filesystem::path kPlants = std::filesystem::path(PLANTFIELD_DATA_DIR) / "plants";

TEST(SceneLoad, DefaultSceneIsAMixedForestWithACameraPath) {
    const Scene scene = loadScene(kScenes / "default.json");
    std::set<std::string> names;
    for (const Species& s : scene.species) {
        names.insert(s.name);
        EXPECT_TRUE(std::filesystem::is_regular_file(s.lsystem)) << s.lsystem;
    }
    EXPECT_EQ(names, (std::set<std::string>{"broadleaf", "spruce", "bush", "grass"}));
    EXPECT_TRUE(std::holds_alternative<NoiseHeightfield>(scene.terrain.heightfield));
    EXPECT_GT(std::get<NoiseHeightfield>(scene.terrain.heightfield).amplitude, 0.0f); // rolling, not flat
    EXPECT_GE(scene.camera.keyframes.size(), 2u);
}

TEST(SceneLoad, SmallTestSceneLoadsCountAndExplicitPlacement) {
    const Scene scene = loadScene(kScenes / "test_small.json");
    ASSERT_EQ(scene.species.size(), 2u);
    EXPECT_EQ(scene.species[0].placement.mode, PlacementMode::Count);
    EXPECT_EQ(scene.species[0].placement.count, 20u);
    EXPECT_EQ(scene.species[0].steps, 3u);
    const std::vector<PlacedPlant> expected = {{{0, 0}, 0, 1}, {{8, -5}, 90, 1.5f}};
    EXPECT_EQ(scene.species[1].placement.mode, PlacementMode::Explicit);
    EXPECT_EQ(scene.species[1].placement.instances, expected);
    EXPECT_EQ(scene.species[1].lsystem, kPlants / "abop_1_24c.lsys");
}

TEST(SceneLoad, EveryOmittedKeyTakesItsDefault) {
    const auto file = test::writeFile("minimal.json", "{ \"species\": [ { \"name\": \"a\", " PF_BUSH_LSYSTEM " } ] }");
    Scene expected;
    expected.file = file;
    expected.species.push_back({.name = "a", .lsystem = kPlants / "stochastic_bush.lsys"});
    EXPECT_EQ(loadScene(file), expected);
}

// Every key of the format, each with a value other than its default.
constexpr const char* kFullScene = R"({
  "description": "every key",
  "seed": 99,
  "terrain": {
    "size": 120, "resolution": 65, "albedo": [0.2, 0.3, 0.1],
    "noise": { "seed": 5, "octaves": 3, "amplitude": 4, "frequency": 0.02, "lacunarity": 2.5, "gain": 0.4 },
    "lsystem": { "path": "terrain/hills.lsys", "origin": [5, -5], "heading": 30, "scale": 2, "max_height": 50, "seed": 3 }
  },
  "placement": { "min_distance": 3, "clearance": 2, "max_slope": 20, "height_range": [-1, 9], "scale": [0.5, 2], "seed": 11 },
  "species": [
    {
      "name": "tree", "lsystem": "plants/tree.lsys", "defines": { "r1": 0.8, "a_0": 30 }, "steps": 6,
      "variants": 3, "seed": 17, "height": 9.5,
      "lod": { "billboard": "triple", "reduced_below_px": 200, "impostor_below_px": 64 },
      "materials": { "leaf": [0.1, 0.5, 0.1], "9": [0.3, 0.2, 0.1] },
      "placement": { "count": 12 }
    },
    {
      "name": "grass", "lsystem": "plants/tree.lsys",
      "placement": { "instances": [ { "position": [1, 2], "rotation": 45, "scale": 0.5 } ] }
    }
  ],
  "sun": { "elevation": 20, "azimuth": 200, "colour": [1, 0.9, 0.8], "intensity": 3 },
  "sky": { "zenith": [0.1, 0.2, 0.5], "horizon": [0.7, 0.8, 0.9] },
  "fog": { "density": 0.01 },
  "wind": { "speed": 7, "direction": 270, "gust_strength": 0.9, "gust_speed": 8, "turbulence": 0.5 },
  "clouds": [ { "lsystem": "clouds/puff.lsys", "position": [0, 150, -300], "size": 120, "seed": 4 } ],
  "camera": {
    "fov": 55, "near": 0.5, "far": 900,
    "keyframes": [
      { "time": 0, "position": [0, 2, 10], "target": [0, 1, 0], "fov": 40 },
      { "time": 4.5, "position": [10, 3, 0], "target": [0, 1, 0] }
    ]
  }
})";

Scene fullSceneExpected(const std::filesystem::path& file) {
    Scene s;
    s.file = file;
    s.description = "every key";
    s.seed = 99;
    s.terrain = {120,
                 65,
                 NoiseHeightfield{5, 3, 4, 0.02f, 2.5f, 0.4f},
                 {0.2f, 0.3f, 0.1f},
                 TerrainLsystem{file.parent_path() / "terrain/hills.lsys", {5, -5}, 30, 2, 50, 3, {}}};
    Placement global{.mode = PlacementMode::Distance,
                     .minDistance = 3,
                     .clearance = 2,
                     .maxSlopeDegrees = 20,
                     .heightRange = {-1, 9},
                     .scaleRange = {0.5f, 2},
                     .seed = 11};
    Species tree{.name = "tree",
                 .lsystem = file.parent_path() / "plants/tree.lsys",
                 .defines = {{"r1", 0.8}, {"a_0", 30}},
                 .steps = 6,
                 .variants = 3,
                 .seed = 17,
                 .height = 9.5f,
                 .lod = {BillboardKind::Triple, 200, 64},
                 .materials = {{1, {0.1f, 0.5f, 0.1f}}, {9, {0.3f, 0.2f, 0.1f}}},
                 .placement = global};
    tree.placement.mode = PlacementMode::Count;
    tree.placement.count = 12;
    Species grass{.name = "grass", .lsystem = tree.lsystem, .placement = global};
    grass.placement.mode = PlacementMode::Explicit;
    grass.placement.instances = {{{1, 2}, 45, 0.5f}};
    s.species = {tree, grass};
    s.sun = {20, 200, {1, 0.9f, 0.8f}, 3};
    s.sky = {{0.1f, 0.2f, 0.5f}, {0.7f, 0.8f, 0.9f}};
    s.fog = {0.01f};
    s.wind = {7, 270, 0.9f, 8, 0.5f};
    s.camera = {{{0, {0, 2, 10}, {0, 1, 0}, 40.0f}, {4.5, {10, 3, 0}, {0, 1, 0}, std::nullopt}}, 55, 0.5f, 900};
    Cloud puff{.lsystem = file.parent_path() / "clouds/puff.lsys", .position = {0, 150, -300}, .size = 120, .seed = 4};
    puff.spheres = cloudSpheres(puff.lsystem, puff.seed, puff.size, puff.position);
    s.clouds = {puff};
    return s;
}

// kFullScene in the test's folder with the plant, terrain and cloud files it
// names (an L-system without mountain modules serves the terrain too: it
// makes no bumps).
std::filesystem::path writeFullScene() {
    test::writeFile("plants/tree.lsys", "Axiom: F\n");
    test::writeFile("terrain/hills.lsys", "Axiom: F\n");
    test::writeFile("clouds/puff.lsys", "Axiom: @O(2) f(1) @O(1.5)\n");
    return test::writeFile("full.json", kFullScene);
}

TEST(SceneLoad, FullySpecifiedSceneReadsBackEveryValue) {
    const auto file = writeFullScene();
    const Scene expected = fullSceneExpected(file);
    // Each value differs from its default, so a key the loader ignored fails.
    const Scene defaults;
    EXPECT_NE(expected.terrain, defaults.terrain);
    EXPECT_NE(expected.sun, defaults.sun);
    EXPECT_NE(expected.sky, defaults.sky);
    EXPECT_NE(expected.fog, defaults.fog);
    EXPECT_NE(expected.wind, defaults.wind);
    EXPECT_NE(expected.camera, defaults.camera);
    EXPECT_NE(expected.clouds, defaults.clouds);
    EXPECT_EQ(loadScene(file), expected);
}

TEST(SceneLoad, FormatDocumentShowsTheFullySpecifiedScene) {
    std::ifstream in(std::filesystem::path(PLANTFIELD_DATA_DIR) / "../docs/SCENE_FORMAT.md");
    const std::string doc(std::istreambuf_iterator<char>(in), {});
    const size_t start = doc.find("```json\n", doc.find("## A complete example"));
    ASSERT_NE(start, std::string::npos);
    const size_t end = doc.find("\n```", start);
    EXPECT_EQ(doc.substr(start + 8, end - start - 8), kFullScene);
}

TEST(SceneLoad, SpeciesPlacementOverridesTheGlobalOneKeyByKey) {
    const auto file = test::writeFile("inherit.json", "{ \"placement\": { \"count\": 5, \"clearance\": 4 },\n"
                                                      "  \"species\": [ { \"name\": \"a\", " PF_BUSH_LSYSTEM " },\n"
                                                      "    { \"name\": \"b\", " PF_BUSH_LSYSTEM
                                                      ", \"placement\": { \"density\": 30 } } ] }");
    const Scene scene = loadScene(file);
    EXPECT_EQ(scene.species[0].placement.mode, PlacementMode::Count);
    EXPECT_EQ(scene.species[0].placement.count, 5u);
    EXPECT_EQ(scene.species[0].placement.clearance, 4.0f);
    EXPECT_EQ(scene.species[1].placement.mode, PlacementMode::Density); // its density replaces the inherited count
    EXPECT_EQ(scene.species[1].placement.densityPerHectare, 30.0f);
    EXPECT_EQ(scene.species[1].placement.clearance, 4.0f);
}

TEST(SceneLoad, ImageHeightfieldResolvesAgainstTheSceneFolder) {
    const auto png = test::writeFile("maps/height.png", "not read by the loader");
    const auto file = test::writeFile(
        "image.json", "{ \"terrain\": { \"image\": { \"path\": \"maps/height.png\", \"height_scale\": 35 } },\n"
                      "  \"species\": [ { \"name\": \"a\", " PF_BUSH_LSYSTEM " } ] }");
    EXPECT_EQ(loadScene(file).terrain.heightfield,
              (std::variant<NoiseHeightfield, ImageHeightfield>{ImageHeightfield{png, 35}}));
}

TEST(SceneLoad, EnvironmentCarriesSunSkyFogAndGround) {
    const Environment env = environmentOf(loadScene(writeFullScene()));
    EXPECT_EQ(env.sunRadiance, glm::vec3(1.0f, 0.9f, 0.8f) * 3.0f);
    EXPECT_EQ(env.sunElevationDegrees, 20.0f);
    EXPECT_EQ(env.skyHorizon, glm::vec3(0.7f, 0.8f, 0.9f));
    EXPECT_EQ(env.fogDensity, 0.01f);
    EXPECT_EQ(env.groundHalfSize, 60.0f);
}

TEST(SceneSeeds, LoadingTwiceGivesTheSameSceneAndSeeds) {
    const Scene a = loadScene(kScenes / "default.json");
    const Scene b = loadScene(kScenes / "default.json");
    EXPECT_EQ(a, b);
    EXPECT_EQ(terrainSeed(a), terrainSeed(b));
    for (size_t i = 0; i < a.species.size(); ++i) {
        EXPECT_EQ(speciesSeed(a, i), speciesSeed(b, i));
        EXPECT_EQ(placementSeed(a, i), placementSeed(b, i));
    }
}

TEST(SceneSeeds, DerivedSeedsAreDistinctAndFollowTheSceneSeed) {
    Scene scene = loadScene(kScenes / "default.json");
    std::set<uint32_t> seeds = {terrainSeed(scene)};
    for (size_t i = 0; i < scene.species.size(); ++i) seeds.insert({speciesSeed(scene, i), placementSeed(scene, i)});
    EXPECT_EQ(seeds.size(), 1 + 2 * scene.species.size());

    const uint32_t before = placementSeed(scene, 0);
    scene.seed += 1;
    EXPECT_NE(placementSeed(scene, 0), before);
}

TEST(SceneSeeds, ExplicitSeedsWin) {
    const Scene scene = loadScene(writeFullScene());
    EXPECT_EQ(terrainSeed(scene), 5u);
    EXPECT_EQ(speciesSeed(scene, 0), 17u);
    EXPECT_EQ(placementSeed(scene, 0), 11u);
    EXPECT_NE(speciesSeed(scene, 1), 17u); // not given: derived
}

} // namespace
} // namespace pf
