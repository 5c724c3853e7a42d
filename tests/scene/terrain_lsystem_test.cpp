// "terrain": { "lsystem": ... } (docs/SCENE_FORMAT.md, docs/TERRAIN_LSYSTEMS.md):
// the L-system's bumps on flat ground or added to noise, its placement keys,
// the file in the build's ReadFileLog, and a malformed file's located error.
#include "engine/scene/field_content.h"
#include "lsystem/common/file_reader.h"
#include "lsystem/landscape/mountain_turtle.h"
#include "lsystem/vlab/object.h"
#include "scene_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// One hill 20 m high and 20 m across (radius) three turtle units along the core.
constexpr const char* kOneHill = "module Hill\nwidth: 4\nAxiom: f(3)[^(90)f(2)Hill]\n";

std::filesystem::path sceneWith(const std::string& terrain) {
    return test::writeFile("scene.json", "{\n  \"terrain\": " + terrain +
                                             ",\n  \"species\": [ { \"name\": \"a\", " PF_BUSH_LSYSTEM " } ]\n}");
}

TEST(TerrainLsystem, AloneItRaisesItsBumpsOnFlatGround) {
    test::writeFile("mountains/hill.lsys", kOneHill);
    const Scene scene =
        loadScene(sceneWith("{ \"size\": 200, \"resolution\": 41, \"lsystem\": \"mountains/hill.lsys\" }"));
    ASSERT_TRUE(scene.terrain.lsystem);
    EXPECT_EQ(scene.terrain.lsystem->path, test::testFolder() / "mountains/hill.lsys");
    ASSERT_EQ(scene.terrain.lsystem->bumps.size(), 1u);
    const Heightfield ground = terrainOf(scene);
    EXPECT_NEAR(heightAt(ground, 30.0f, 0.0f), 20.0f, 1e-4f); // 10 m a turtle unit
    EXPECT_NEAR(heightAt(ground, 40.0f, 0.0f), 10.0f, 1e-4f); // half the hill's radius out
    size_t raised = 0;
    for (uint32_t iz = 0; iz < ground.resolution; ++iz)
        for (uint32_t ix = 0; ix < ground.resolution; ++ix) {
            const float distance = std::hypot(ground.coordinate(ix) - 30.0f, ground.coordinate(iz));
            if (distance >= 20.0f) {
                EXPECT_EQ(ground.height(ix, iz), 0.0f) << ix << ", " << iz;
            } else {
                raised += ground.height(ix, iz) > 0.0f;
            }
        }
    EXPECT_GT(raised, 40u);
}

TEST(TerrainLsystem, WithNoiseItsBumpsAreAddedToTheNoise) {
    test::writeFile("hill.lsys", kOneHill);
    const Scene noisy = loadScene(sceneWith("{ \"size\": 200, \"resolution\": 41, \"noise\": { \"seed\": 4 } }"));
    const Scene both = loadScene(
        sceneWith("{ \"size\": 200, \"resolution\": 41, \"noise\": { \"seed\": 4 }, \"lsystem\": \"hill.lsys\" }"));
    const Heightfield noise = terrainOf(noisy), sum = terrainOf(both);
    ASSERT_EQ(noise.heights.size(), sum.heights.size());
    for (uint32_t iz = 0; iz < sum.resolution; ++iz)
        for (uint32_t ix = 0; ix < sum.resolution; ++ix)
            EXPECT_FLOAT_EQ(
                sum.height(ix, iz) - noise.height(ix, iz),
                lsys::landscape::bumpsHeightAt(both.terrain.lsystem->bumps, sum.coordinate(ix), sum.coordinate(iz)));
    EXPECT_NE(noise.heights, std::vector<float>(noise.heights.size(), 0.0f)); // the noise is there
}

TEST(TerrainLsystem, ItsKeysPlaceTheTurtleAndPickItsSeed) {
    const std::string ridge = std::string(PLANTFIELD_DATA_DIR) + "/terrain/ridge.lsys";
    const Scene scene =
        loadScene(sceneWith(R"({ "lsystem": { "path": ")" + ridge +
                            R"(", "origin": [100, -50], "heading": 90, "scale": 2, "max_height": 90, "seed": 7 } })"));
    const TerrainLsystem& lsystem = *scene.terrain.lsystem;
    EXPECT_EQ(lsystem.origin, glm::vec2(100.0f, -50.0f));
    EXPECT_EQ(lsystem.headingDegrees, 90.0f);
    EXPECT_EQ(lsystem.scale, 2.0f);
    EXPECT_EQ(lsystem.maxHeight, 90.0f);
    EXPECT_EQ(lsystem.seed, 7u);
    lsys::landscape::MountainPlacement placement;
    placement.originX = 100.0f;
    placement.originZ = -50.0f;
    placement.headingDegrees = 90.0f;
    placement.scale = 2.0f;
    placement.maxHeight = 90.0f;
    EXPECT_EQ(lsystem.bumps,
              lsys::landscape::mountainBumpsOf(lsys::vlab::loadPlant(ridge).parsed.grammar, placement, 7));
}

TEST(TerrainLsystem, TheSameSceneGivesTheSameGroundBitForBit) {
    const std::string massif = std::string(PLANTFIELD_DATA_DIR) + "/terrain/massif.lsys";
    const std::filesystem::path file = sceneWith(R"({ "noise": { "seed": 2 }, "lsystem": ")" + massif + "\" }");
    EXPECT_EQ(terrainOf(loadScene(file)).heights, terrainOf(loadScene(file)).heights);
}

TEST(TerrainLsystem, TheLsystemFileIsInTheBuildsReadLog) {
    const std::filesystem::path lsystem = test::writeFile("logged.lsys", kOneHill);
    const lsys::ReadFileLog read;
    loadScene(sceneWith("{ \"lsystem\": \"logged.lsys\" }"));
    EXPECT_NE(std::find(read.paths().begin(), read.paths().end(), lsystem), read.paths().end());
}

// The error points at the scene's key and quotes the L-system's own file:line:column.
TEST(TerrainLsystem, AMalformedLsystemIsALocatedSceneError) {
    const std::filesystem::path lsystem = test::writeFile("broken.lsys", "module Hill\nAxiom: f(1)\nf(x) --> f(x+*)\n");
    const std::string text =
        "{\n  \"terrain\": { \"lsystem\": \"broken.lsys\" },\n  \"species\": [ { \"name\": \"a\", " PF_BUSH_LSYSTEM
        " } ]\n}";
    const std::filesystem::path scene = test::writeFile("bad.json", text);
    try {
        loadScene(scene);
        FAIL() << "loaded without an error";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(scene.string() + ":" + test::lineColumnOf(text, "\"broken.lsys\"") + ": ", 0), 0u) << what;
        EXPECT_NE(what.find("/terrain/lsystem names a malformed L-system"), std::string::npos) << what;
        EXPECT_NE(what.find(lsystem.string() + ":3:"), std::string::npos) << what;
    }
}

} // namespace
} // namespace pf
