// plantfield frames from cameras and fields at the edges of what a scene
// may hold: straight down, millions of metres out, a field with no plant,
// and more variants than the impostor atlas holds. Each compares pixel
// statistics of the capture, not a golden.
#include "run_command.h"

#include "engine/image/image.h"
#include "options.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>

namespace pf::test {
namespace {

namespace fs = std::filesystem;

const fs::path kScenesDir = fs::path(defaultScenePath()).parent_path();

fs::path camerasScratch(const std::string& name) {
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "cameras" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// data/scenes/<scene> with its plants' paths made absolute and `change`
// applied, written into `dir`.
template <typename Change>
fs::path changedScene(const fs::path& dir, const std::string& scene, Change change) {
    nlohmann::json json = nlohmann::json::parse(std::ifstream(kScenesDir / scene));
    for (nlohmann::json& species : json.at("species"))
        species["lsystem"] = (kScenesDir / species.at("lsystem").get<std::string>()).lexically_normal().string();
    change(json);
    const fs::path file = dir / scene;
    std::ofstream(file) << json.dump(2);
    return file;
}

nlohmann::json oneKey(const std::array<float, 3>& position, const std::array<float, 3>& target) {
    return nlohmann::json::array({{{"time", 0}, {"position", position}, {"target", target}}});
}

struct PixelStats {
    size_t colours = 0;  // distinct RGB values
    double mean = 0.0;   // of r + g + b
    double spread = 0.0; // standard deviation of r + g + b
};

PixelStats statsOf(const RgbaImage& image) {
    std::set<uint32_t> colours;
    double sum = 0.0, squares = 0.0;
    const size_t pixels = size_t(image.width) * image.height;
    for (size_t i = 0; i < pixels; ++i) {
        const uint8_t* p = &image.pixels[i * 4];
        colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
        const double value = p[0] + p[1] + p[2];
        sum += value;
        squares += value * value;
    }
    const double mean = sum / double(pixels);
    return {colours.size(), mean, std::sqrt(std::max(0.0, squares / double(pixels) - mean * mean))};
}

// Captures `scene` at `size`; the run must succeed under the validation layer.
PixelStats capture(const fs::path& scene, const std::string& size = "160x90") {
    const fs::path out = scene.parent_path() / (scene.stem().string() + ".png");
    const CommandResult r = runCommand(std::string(PLANTFIELD_BIN) + " " + scene.string() + " --validation --size " +
                                       size + " --capture " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    return r.exitCode == 0 ? statsOf(readPng(out.string())) : PixelStats{};
}

// Looking straight down the look-at basis had no right vector: a NaN view
// and a frame of one colour.
TEST(PlantfieldCameras, StraightDownOnTheDefaultSceneShowsPlantsAndTerrain) {
    const fs::path dir = camerasScratch("straight-down");
    const fs::path scene = changedScene(dir, "default.json", [](nlohmann::json& json) {
        json["camera"]["keyframes"] = oneKey({10, 60, -5}, {10, 0, -5});
    });
    const PixelStats stats = capture(scene);
    EXPECT_GT(stats.colours, 200u);
    EXPECT_GT(stats.spread, 10.0);
}

// The same framing from 10^5 m and from 3·10^6 m (the field of view
// narrowed 30 times): from the second, with the scene's 0.1 m near plane,
// every depth rounded to the far plane and nothing but sky was drawn.
TEST(PlantfieldCameras, AFieldMillionsOfMetresAwayIsDrawnAsFromAHundredKilometres) {
    const fs::path dir = camerasScratch("far");
    PixelStats stats[2];
    const float distances[2] = {1e5f, 3e6f};
    for (int i = 0; i < 2; ++i) {
        const float d = distances[i];
        const fs::path scene =
            changedScene(camerasScratch("far/" + std::to_string(i)), "test_small.json", [d](nlohmann::json& json) {
                json["fog"] = {{"density", 0}};
                // 60 m of the field fill the frame's height.
                json["camera"]["fov"] = 2.0 * std::atan(30.0 / d) * 180.0 / std::numbers::pi;
                json["camera"]["keyframes"] = oneKey({0, 0.6f * d, 0.8f * d}, {0, 1, 0});
            });
        stats[i] = capture(scene);
    }
    EXPECT_GT(stats[0].colours, 50u) << "from 10^5 m";
    EXPECT_GT(stats[1].colours, 50u) << "from 3·10^6 m";
    EXPECT_NEAR(stats[1].mean, stats[0].mean, 15.0);
    EXPECT_NEAR(stats[1].spread, stats[0].spread, 15.0);
}

// An empty field is a valid field: its terrain and sky render.
TEST(PlantfieldCameras, ASceneWhoseOnlySpeciesPlacesNoPlantRendersTerrainAndSky) {
    const fs::path dir = camerasScratch("empty");
    const fs::path scene = changedScene(dir, "test_small.json", [](nlohmann::json& json) {
        json["species"] = nlohmann::json::array({json["species"][0]});
        json["species"][0]["placement"] = {{"count", 0}};
        json["camera"]["keyframes"] = oneKey({0, 4, 25}, {0, 4, 0});
    });
    const PixelStats stats = capture(scene);
    EXPECT_GT(stats.colours, 20u) << "terrain below the horizon, sky above";
    EXPECT_GT(stats.spread, 10.0);
}

// 171 variants and test_small.json's tree are 172 models, 6 192 atlas layers
// at 36 a model, past the 2 048 of lavapipe and most GPUs: the variants share
// the frames of a few.
TEST(PlantfieldCameras, MoreVariantsThanTheImpostorAtlasHoldsRender) {
    const fs::path dir = camerasScratch("variants");
    const fs::path scene = changedScene(dir, "test_small.json", [](nlohmann::json& json) {
        json["species"][0]["variants"] = 171;
        json["species"][0]["steps"] = 1;
    });
    const PixelStats stats = capture(scene, "96x54");
    EXPECT_GT(stats.colours, 20u);
}

} // namespace
} // namespace pf::test
