// plantfield with plants of all three kinds (Tankard 2001): L-systems,
// ramification trees (.ram.json) and component plants (.comp.json), in the
// modellers scene and in --plant previews, under the validation layer.
#include "run_command.h"

#include "options.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace pf::test {
namespace {

namespace fs = std::filesystem;

std::string plantfieldBinary() { return PLANTFIELD_BIN; }

const fs::path modelsDataDir = fs::path(defaultScenePath()).parent_path().parent_path();

fs::path modelsScratch(const std::string& name) {
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / "models" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(PlantfieldModels, ModellersSceneBuildsEveryModelUnderValidation) {
    const fs::path scene = modelsDataDir / "scenes" / "modellers.json";
    const nlohmann::json file = nlohmann::json::parse(std::ifstream(scene));
    uint64_t variants = 0;
    bool ramified = false, components = false;
    for (const nlohmann::json& species : file.at("species")) {
        variants += species.value("variants", 1u);
        const std::string model = species.value("model", "");
        ramified |= model.ends_with(".ram.json");
        components |= model.ends_with(".comp.json");
    }
    ASSERT_TRUE(ramified && components) << "the scene lacks a kind of model";

    const fs::path out = modelsScratch("modellers") / "modellers.png";
    const CommandResult r = runCommand(plantfieldBinary() + " " + scene.string() +
                                       " --validation --stats --size 160x90 --capture " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_regular_file(out));
    const size_t start = r.output.find('{');
    ASSERT_NE(start, std::string::npos) << r.output;
    const nlohmann::json stats = nlohmann::json::parse(r.output.substr(start, r.output.find("\n}", start) + 2 - start));
    EXPECT_EQ(stats.at("models").get<uint64_t>(), variants);
}

TEST(PlantfieldModels, PlantPreviewTakesTreeTypesAndComponentPlants) {
    const fs::path dir = modelsScratch("preview");
    for (const char* plant : {"ramified/pine.ram.json", "components/sunflower.comp.json"}) {
        const fs::path out = dir / (fs::path(plant).stem().string() + ".png");
        const CommandResult r = runCommand(plantfieldBinary() + " --validation --size 64x64 --plant " +
                                           (modelsDataDir / plant).string() + " --capture " + out.string());
        EXPECT_EQ(r.exitCode, 0) << plant << "\n" << r.output;
        EXPECT_EQ(r.output.find("validation"), std::string::npos) << plant << "\n" << r.output;
        EXPECT_TRUE(fs::is_regular_file(out)) << plant;
    }
}

// --steps and -D derive L-systems: with a model they are refused, naming the
// file, before anything is built or written.
TEST(PlantfieldModels, DerivationOptionsWithAModelAreRefused) {
    const fs::path out = modelsScratch("refused") / "never.png";
    for (const char* option : {"--steps 3", "-D N=2"}) {
        const std::string model = (modelsDataDir / "components/sunflower.comp.json").string();
        const CommandResult r =
            runCommand(plantfieldBinary() + " --plant " + model + " " + option + " --capture " + out.string());
        EXPECT_EQ(r.exitCode, 2) << option << "\n" << r.output;
        EXPECT_NE(r.output.find("--steps and -D derive an L-system; " + model + " is a model"), std::string::npos)
            << r.output;
        EXPECT_FALSE(fs::exists(out)) << option;
    }
}

} // namespace
} // namespace pf::test
